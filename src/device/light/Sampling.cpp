#include "Sampling.h"

#include <algorithm>
#include <cmath>

namespace prism::light {

double integrateOverSphere(const std::function<double(double theta)> &f,
    std::vector<double> breakpoints)
{
  breakpoints.push_back(0.0);
  breakpoints.push_back(kPiDouble);
  for (double &b : breakpoints)
    b = clamp(b, 0.0, kPiDouble);
  std::sort(breakpoints.begin(), breakpoints.end());
  constexpr int kIntervals = 64; // per piece, even for Simpson
  double sum = 0.0;
  for (size_t i = 0; i + 1 < breakpoints.size(); i++) {
    const double begin = breakpoints[i], end = breakpoints[i + 1];
    if (!(end > begin))
      continue;
    const double h = (end - begin) / kIntervals;
    // Jumps sit on breakpoints: evaluate just inside each piece so a step
    // belongs to the piece it bounds.
    const double inset = h * 1e-9;
    auto g = [&](int k) {
      double theta = begin + k * h;
      theta = k == 0 ? begin + inset : (k == kIntervals ? end - inset : theta);
      return f(theta) * std::sin(theta);
    };
    double piece = g(0) + g(kIntervals);
    for (int k = 1; k < kIntervals; k++)
      piece += (k % 2 ? 4.0 : 2.0) * g(k);
    sum += piece * h / 3.0;
  }
  return 2.0 * kPiDouble * sum;
}

} // namespace prism::light
