// The base of every ANARI object: reference counts, staged and committed
// parameters, the pull-model parameter readers, properties and status.
#pragma once

#include "ContentHash.h"
#include "DeclaredParameter.h"
#include "DeclaredType.h"
#include "ObjectRef.h"
#include "Parameter.h"

#include <atomic>
#include <cstdarg>
#include <mutex>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

namespace prism {
class DeviceState;

class Object
{
 public:
  Object(DeviceState &device, ANARIDataType type, std::string subtype);
  virtual ~Object();
  Object(const Object &) = delete;
  Object &operator=(const Object &) = delete;

  ANARIDataType type() const
  {
    return m_type;
  }
  const std::string &subtype() const
  {
    return m_subtype;
  }
  DeviceState &device() const
  {
    return m_device;
  }
  // The C handle the application sees for this object.
  ANARIObject handle() const
  {
    return m_handle;
  }
  void setHandle(ANARIObject handle)
  {
    m_handle = handle;
  }

  // Reference counts (spec 3.5): the object lives while either count is
  // positive; the handle is valid while the public count is.
  void retainPublic();
  uint32_t dropPublicReference(); // returns the remaining public count
  // Internal references are what objects hold on one another; const, since
  // a holder may see its child as const.
  void retainInternal() const;
  void releaseInternal() const;
  uint32_t publicReferences() const
  {
    return m_publicRefs.load();
  }
  // Public and internal references together.
  uint32_t totalReferences() const
  {
    return m_totalRefs.load();
  }

  // Staging (any thread; never visible to rendering until committed).
  void stageParameter(const std::string &name, Parameter value);
  void unstageParameter(const std::string &name);
  void unstageAllParameters();
  bool hasStagedParameter(const std::string &name) const;
  // anariCommitParameters: freezes the staged values for the next flush.
  void snapshotForCommit();
  // Runs commitParameters() on the frozen values, then warns about values
  // that were set but never read or had a type the object does not accept.
  void applyCommit();
  // Builds derived state after every object of a flush has been committed.
  virtual void finalize() {}
  // Whether renderers may use this object.
  virtual bool isValid() const
  {
    return true;
  }
  // Incremented on every commit; parents compare it to rebuild lazily.
  uint64_t epoch() const
  {
    return m_epoch.load();
  }
  void markChanged()
  {
    m_epoch++;
  }

  // A hash of what this object renders with, so processes that must hold
  // the same objects can compare them: its type, subtype and committed
  // parameters (objects by their own contentHash(), strings by their text,
  // other values by their bytes; pointers and callbacks by name and type
  // only, since addresses differ by process; "name" not at all); arrays
  // add their elements in use. Computed at the first call after a change
  // and kept until the next (by epoch()), so shared children and unchanged
  // arrays are hashed once. Call it after refresh(), on the thread that
  // flushes commits (nothing here is locked).
  uint64_t contentHash() const;

  // anariGetProperty; returns true when `mem` was written.
  virtual bool getProperty(const std::string &name,
      ANARIDataType type,
      void *mem,
      uint64_t size,
      ANARIWaitMask mask);

  // The values the last commit read (a data-parallel device sends a light
  // to other processes by them). Call on the thread that flushes commits.
  const ParameterStore &committedParameters() const
  {
    return m_committed;
  }

  // The names the last commit asked for, set or not (conformance checks:
  // everything an object reads must be declared to introspection).
  const std::set<std::string> &parametersRead() const
  {
    return m_readThisCommit;
  }
  // The names param() was asked for that introspection does not declare
  // for this object's type and subtype (a device bug; conformance tests
  // require none, debug builds also report them).
  const std::set<std::string> &undeclaredParametersRead() const
  {
    return m_undeclaredReads;
  }

  // Drops every reference this object holds on others (device teardown).
  virtual void dropReferences();

  // Re-applies this object's commit when an object it read (an array that
  // was unmapped, a child that was recommitted) changed since; children
  // first. Runs at most once per `generation` (one per frame start).
  void refresh(uint64_t generation);
  // refresh() of every object this one read, but not of this one: what a
  // commit just read is brought up to date before finalize() builds on it.
  void refreshDependencies(uint64_t generation);

  // Reports a message naming this object, its type and subtype.
  void report(ANARIStatusSeverity severity,
      ANARIStatusCode code,
      const char *format,
      ...) const __attribute__((format(printf, 4, 5)));
  // "geometry 'sphere' (name)" for messages.
  std::string describe() const;

 protected:
  // Reads committed parameters; called once per commit.
  virtual void commitParameters() {}
  // Feeds what contentHash() covers beyond type and subtype.
  virtual void hashContent(ContentHash &hash) const;
  // Whether contentHash() may be kept until epoch() changes; false for
  // objects whose content can change while their epoch does not.
  virtual bool keepsContentHash() const
  {
    return true;
  }

  // Pull-model readers: each marks the parameter as read and checks its
  // type; a mismatch is warned about once and the fallback returned.
  template <typename T>
  T read(const char *name, ANARIDataType expected, T fallback)
  {
    const Parameter *p = readAny(name);
    if (!p)
      return fallback;
    if (p->type() != expected) {
      wrongType(name, p->type(), {expected});
      return fallback;
    }
    return p->template as<T>();
  }
  // Declared parameters: the definition of this object's type and subtype
  // in the introspection tables gives the type T must be, the default, the
  // bounds and the accepted values. Returns the value set; the default
  // when it is unset or set with another type (warned once, see
  // wrongType()), not a number or not an accepted value; a number beyond
  // the bounds clamped to the nearest one. A value not taken as set is
  // reported as a warning naming the range, each commit.
  template <typename T>
  T param(const char *name)
  {
    T value;
    const ParamCheck check = checkedParam(name, value);
    if (check.verdict != ParamVerdict::kAccepted)
      reportRejected(check);
    return value;
  }
  // The same, not reporting: `value` is what param() would return, the
  // check says why it is not the value set.
  template <typename T>
  ParamCheck checkedParam(const char *name, T &value)
  {
    if constexpr (std::is_same_v<T, std::string>) {
      return readDeclaredString(name, value);
    } else if constexpr (std::is_same_v<T, bool>) {
      uint8_t byte = 0;
      const ParamCheck check =
          readDeclared(name, ANARI_BOOL, &byte, sizeof(byte));
      value = byte != 0;
      return check;
    } else {
      return readDeclared(name, declaredType<T>(), &value, sizeof(T));
    }
  }
  bool readBool(const char *name, bool fallback);
  std::string readString(const char *name, const std::string &fallback);
  // An object parameter of exactly one of `accepted` types, or NULL.
  Object *readObject(
      const char *name, std::initializer_list<ANARIDataType> accepted);
  // The raw parameter (marked read, no type check), or NULL if unset.
  const Parameter *readAny(const char *name);
  bool isSet(const char *name) const;
  // Whether the definitions declare `name` for this type and subtype.
  bool declares(const char *name) const;
  // Marks every committed parameter as read (objects that accept anything).
  void readAll();
  // Makes refresh() re-commit this object when `object` changes (objects
  // read with readObject() are recorded automatically). Until the next
  // commit, the dependency also keeps `object` alive, so what a commit
  // derived from it (pointers into it) stays valid whatever the
  // application releases or remaps meanwhile.
  void dependOn(Object *object);
  // Warns that a value was not taken as set, and what was used instead.
  void reportRejected(const ParamCheck &check);
  // Records that `name` was set with an unsupported type.
  void wrongType(const char *name,
      ANARIDataType given,
      const std::vector<ANARIDataType> &accepted);

 private:
  void reportUnusedParameters();
  // checkedParam() on the C bytes of `type` (`size` of them written to
  // `out`).
  ParamCheck readDeclared(
      const char *name, ANARIDataType type, void *out, size_t size);
  ParamCheck readDeclaredString(const char *name, std::string &out);
  // The declaration of `name` for this object; nullptr (recorded) if none.
  const introspection::ParameterDefinition *declaration(const char *name);

  DeviceState &m_device;
  const ANARIDataType m_type;
  const std::string m_subtype;
  ANARIObject m_handle{nullptr};
  std::atomic<uint32_t> m_publicRefs{1};
  mutable std::atomic<uint32_t> m_totalRefs{1};
  std::atomic<uint64_t> m_epoch{0};

  mutable std::mutex m_parameterMutex;
  ParameterStore m_staged;
  ParameterStore m_pending;   // frozen at anariCommitParameters
  ParameterStore m_committed; // what commitParameters() reads, from a flush
  bool m_hasPending{false};
  std::set<std::string> m_readThisCommit;
  std::set<std::string> m_warned;
  std::set<std::string> m_undeclaredReads;
  struct Dependency
  {
    ObjectRef<Object> object;
    uint64_t epoch;
  };
  std::vector<Dependency> m_dependencies;
  uint64_t m_refreshedGeneration{0};
  std::string m_name;
  mutable uint64_t m_hashedEpoch{~0ull};
  mutable uint64_t m_contentHash{0};
  mutable bool m_hashing{false}; // reference cycles count once
};

} // namespace prism
