#include "pose.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "solve_command.h"

namespace aspects {

namespace {

std::string pose_names(const Model& m) {
  std::string s;
  for (size_t j = 0; j < m.pose.size(); ++j) s += (j ? "," : "") + m.vars[m.pose[j]].name;
  return s;
}

}  // namespace

std::vector<double> parse_pose(const std::string& text, const std::string& option,
                               const Model& model) {
  const std::string usage = option + " expects " + std::to_string(model.pose.size()) +
                            " numbers separated by commas (" + pose_names(model) + ")";
  std::vector<double> pose;
  size_t start = 0;
  while (true) {
    size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? comma : comma - start);
    const char* b = item.c_str();
    char* end = nullptr;
    errno = 0;
    double x = std::strtod(b, &end);
    while (end && (*end == ' ' || *end == '\t')) ++end;
    if (end == b || *end != '\0' || errno == ERANGE || !std::isfinite(x))
      throw UsageError(usage + ", got '" + text + "' ('" + item + "' is not a finite number)");
    pose.push_back(x);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (pose.size() != model.pose.size())
    throw UsageError(usage + ", got " + std::to_string(pose.size()) + " in '" + text + "'");
  for (size_t j = 0; j < pose.size(); ++j) {
    const Variable& v = model.vars[model.pose[j]];
    if (v.periodic) continue;
    if (!v.domain.contains(pose[j])) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "%s: %s = %.17g is outside its declared domain [%.17g, %.17g]",
                    option.c_str(), v.name.c_str(), pose[j], v.domain.lo_down(), v.domain.hi_up());
      throw UsageError(buf);
    }
  }
  return pose;
}

bool coordinate_in(double p, double lo, double hi, bool periodic) {
  if (lo <= p && p <= hi) return true;
  if (!periodic) return false;
  const double two_pi = 2 * M_PI;
  double kc = std::nearbyint((0.5 * lo + 0.5 * hi - p) / two_pi);
  for (double k = kc - 1; k <= kc + 1; ++k) {
    if (k == 0) continue;
    Interval t;
    mpfi_const_pi(t.get());
    mpfi_mul_d(t.get(), t.get(), 2 * k);
    mpfi_add_d(t.get(), t.get(), p);
    if (lo <= t.lo_down() && t.hi_up() <= hi) return true;
  }
  return false;
}

bool pose_in_box(const Model& m, const std::vector<double>& pose, const double* lo,
                 const double* hi) {
  for (size_t j = 0; j < pose.size(); ++j) {
    int v = m.pose[j];
    if (!coordinate_in(pose[j], lo[v], hi[v], m.vars[v].periodic)) return false;
  }
  return true;
}

double pose_distance(const std::vector<double>& a, const std::vector<double>& b,
                     const std::vector<bool>& periodic) {
  double s = 0;
  for (size_t j = 0; j < a.size(); ++j) {
    double d = std::fabs(a[j] - b[j]);
    if (periodic[j]) d = std::fabs(std::remainder(d, 2 * M_PI));
    s += d * d;
  }
  return std::sqrt(s);
}

std::string format_pose(const std::vector<double>& pose) {
  std::string s;
  char buf[40];
  for (size_t j = 0; j < pose.size(); ++j) {
    std::snprintf(buf, sizeof buf, "%s%.10g", j ? ", " : "", pose[j]);
    s += buf;
  }
  return "(" + s + ")";
}

}  // namespace aspects
