// Collects the messages a device or the front-end reports, for assertions.
#pragma once

#include <anari/anari.h>

#include <mutex>
#include <string>
#include <vector>

struct StatusMessage
{
  ANARIStatusSeverity severity;
  ANARIStatusCode code;
  std::string text;
  ANARIObject source = nullptr; // the object the message is about
};

class StatusRecorder
{
 public:
  static void callback(const void *userPtr,
      ANARIDevice,
      ANARIObject source,
      ANARIDataType,
      ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const char *message)
  {
    auto *self = (StatusRecorder *)userPtr;
    std::lock_guard lock(self->m_mutex);
    self->m_messages.push_back(
        {severity, code, message ? message : "", source});
  }

  std::vector<StatusMessage> take()
  {
    std::lock_guard lock(m_mutex);
    auto out = std::move(m_messages);
    m_messages.clear();
    return out;
  }

  // Whether exactly one message arrived, with this severity, code and a
  // text containing `fragment`.
  bool tookOne(ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const std::string &fragment)
  {
    auto messages = take();
    return messages.size() == 1 && messages[0].severity == severity
           && messages[0].code == code
           && messages[0].text.find(fragment) != std::string::npos;
  }

 private:
  std::mutex m_mutex;
  std::vector<StatusMessage> m_messages;
};
