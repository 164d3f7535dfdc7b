#include "GltfAnimation.h"

#include <algorithm>
#include <cmath>

namespace prism::scene_io {
namespace {

// Where `time` falls among the key times: the keys before and after it
// and how far between them (0 to 1).
struct KeySpan
{
  size_t before{0}, after{0};
  double t{0.0};
  double duration{0.0}; // seconds between the two keys
};

KeySpan findSpan(const std::vector<float> &times, double time)
{
  KeySpan span;
  if (times.empty() || time <= times.front())
    return span;
  if (time >= times.back()) {
    span.before = span.after = times.size() - 1;
    return span;
  }
  const size_t after =
      size_t(std::upper_bound(times.begin(), times.end(), float(time))
             - times.begin());
  span.before = after - 1;
  span.after = after;
  span.duration = double(times[after]) - double(times[after - 1]);
  span.t =
      span.duration > 0.0 ? (time - times[after - 1]) / span.duration : 0.0;
  return span;
}

// Spherical interpolation of unit quaternions, the shorter way round.
void slerp(const double *a, const double *b, double t, double *out)
{
  double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  double sign = 1.0;
  if (dot < 0.0) {
    dot = -dot;
    sign = -1.0;
  }
  double wa = 1.0 - t, wb = t;
  if (dot < 0.9995) {
    const double angle = std::acos(std::min(dot, 1.0));
    wa = std::sin((1.0 - t) * angle) / std::sin(angle);
    wb = std::sin(t * angle) / std::sin(angle);
  }
  double length = 0.0;
  for (int i = 0; i < 4; i++) {
    out[i] = wa * a[i] + sign * wb * b[i];
    length += out[i] * out[i];
  }
  length = std::sqrt(length);
  for (int i = 0; i < 4 && length > 0.0; i++)
    out[i] /= length;
}

// The channel's value at `span` (`width` numbers; CUBICSPLINE outputs hold
// in-tangent, value, out-tangent per key).
std::vector<double> sample(const std::vector<float> &output,
    const KeySpan &span,
    size_t width,
    const std::string &interpolation,
    bool rotation)
{
  const bool cubic = interpolation == "CUBICSPLINE";
  const size_t stride = cubic ? 3 * width : width;
  auto value = [&](size_t key, size_t part, size_t i) {
    return double(output[key * stride + part * width + i]);
  };
  const size_t valuePart = cubic ? 1 : 0;
  std::vector<double> out(width);
  if (span.before == span.after || interpolation == "STEP") {
    for (size_t i = 0; i < width; i++)
      out[i] = value(span.before, valuePart, i);
  } else if (cubic) {
    // Hermite: p0, out-tangent of key 0, p1, in-tangent of key 1, tangents
    // scaled by the keys' distance in time (glTF 2.0, Appendix C).
    const double t = span.t, t2 = t * t, t3 = t2 * t, d = span.duration;
    for (size_t i = 0; i < width; i++)
      out[i] = (2 * t3 - 3 * t2 + 1) * value(span.before, 1, i)
               + (t3 - 2 * t2 + t) * d * value(span.before, 2, i)
               + (-2 * t3 + 3 * t2) * value(span.after, 1, i)
               + (t3 - t2) * d * value(span.after, 0, i);
  } else if (rotation) {
    double a[4], b[4];
    for (size_t i = 0; i < 4; i++) {
      a[i] = value(span.before, 0, i);
      b[i] = value(span.after, 0, i);
    }
    slerp(a, b, span.t, out.data());
  } else {
    for (size_t i = 0; i < width; i++)
      out[i] = (1.0 - span.t) * value(span.before, 0, i)
               + span.t * value(span.after, 0, i);
  }
  if (rotation && cubic) {
    double length = 0.0;
    for (double v : out)
      length += v * v;
    for (double &v : out)
      v = length > 0.0 ? v / std::sqrt(length) : v;
  }
  return out;
}

bool applyChannel(tinygltf::Model &model,
    const tinygltf::Animation &animation,
    const tinygltf::AnimationChannel &channel,
    double time,
    FloatAccessorReader read,
    std::string &error)
{
  const int node = channel.target_node;
  if (node < 0 || size_t(node) >= model.nodes.size()) {
    error = "targets node " + std::to_string(node) + ", which does not exist";
    return false;
  }
  if (channel.sampler < 0
      || size_t(channel.sampler) >= animation.samplers.size()) {
    error = "uses sampler " + std::to_string(channel.sampler)
            + ", which does not exist";
    return false;
  }
  tinygltf::Node &target = model.nodes[size_t(node)];
  const std::string &path = channel.target_path;
  std::vector<double> *property = path == "translation" ? &target.translation
                                  : path == "rotation"  ? &target.rotation
                                  : path == "scale"     ? &target.scale
                                  : path == "weights"   ? &target.weights
                                                        : nullptr;
  if (!property || !target.matrix.empty())
    return true; // unknown paths and matrix nodes are not animated
  const tinygltf::AnimationSampler &sampler =
      animation.samplers[size_t(channel.sampler)];
  std::vector<float> times, output;
  if (!read(model, sampler.input, 1, 1, times, error)
      || !read(model, sampler.output, 1, 4, output, error))
    return false;
  const bool cubic = sampler.interpolation == "CUBICSPLINE";
  const size_t keys = times.size();
  const size_t perKey = cubic ? 3 * keys : keys;
  if (keys == 0 || perKey == 0 || output.size() % perKey != 0) {
    error = "has " + std::to_string(keys) + " key times and "
            + std::to_string(output.size()) + " output values";
    return false;
  }
  const size_t width = output.size() / perKey;
  const size_t expected = path == "rotation" ? 4 : path == "weights" ? 0 : 3;
  if (expected && width != expected) {
    error =
        "animates " + path + " with " + std::to_string(width) + " values a key";
    return false;
  }
  *property = sample(output,
      findSpan(times, time),
      width,
      sampler.interpolation,
      path == "rotation");
  return true;
}

} // namespace

bool poseAtTime(tinygltf::Model &model,
    double time,
    FloatAccessorReader read,
    std::string &error)
{
  // NaN would fall between no two keys (and past the last one's index).
  if (!std::isfinite(time)) {
    error = "the animation time " + std::to_string(time) + " is not finite";
    return false;
  }
  for (size_t a = 0; a < model.animations.size(); a++) {
    const tinygltf::Animation &animation = model.animations[a];
    for (size_t c = 0; c < animation.channels.size(); c++) {
      if (!applyChannel(
              model, animation, animation.channels[c], time, read, error)) {
        error = "animation " + std::to_string(a) + " channel "
                + std::to_string(c) + " " + error;
        return false;
      }
    }
  }
  return true;
}

} // namespace prism::scene_io
