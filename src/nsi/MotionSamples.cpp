#include "MotionSamples.h"

#include <iterator>

namespace prism::nsi {

bool isMoving(const Attribute &attribute)
{
  return !attribute.value && attribute.samples.size() > 1;
}

bool numberSamples(const Attribute &attribute, NumberSamples &samples)
{
  samples.clear();
  bool sameLength = true;
  for (const auto &[time, value] : attribute.samples) {
    auto &numbers = samples[time] = value.numbers();
    sameLength = sameLength && numbers.size() == samples.begin()->second.size();
  }
  return sameLength;
}

std::vector<double> numbersAt(const NumberSamples &samples, double time)
{
  if (samples.empty())
    return {};
  auto after = samples.lower_bound(time);
  if (after == samples.begin())
    return after->second;
  if (after == samples.end())
    return std::prev(after)->second;
  const auto before = std::prev(after);
  const double w = (time - before->first) / (after->first - before->first);
  std::vector<double> out(before->second.size());
  for (size_t i = 0; i < out.size() && i < after->second.size(); ++i)
    out[i] = before->second[i] + w * (after->second[i] - before->second[i]);
  return out;
}

} // namespace prism::nsi
