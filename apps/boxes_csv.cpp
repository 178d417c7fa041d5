#include "boxes_csv.h"

#include <cstdio>

#include "io/atomic_file.h"

namespace aspects {

namespace {

std::string fmt_double(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);  // round-trips exactly
  return buf;
}

std::string header(const Model& m) {
  std::string h = "id,status,csnc,kept";
  for (const auto& v : m.vars) h += ',' + v.name + "_lo," + v.name + "_hi";
  return h + ",boundary\n";
}

void append_row(const AspectsResult& r, int b, std::string& buf) {
  const BoxStore& boxes = r.boxes.ends();
  const int c = r.csnc[b];
  const bool solution = r.boxes.certified(b);
  const bool unexplored = r.boxes.unexplored(b);
  buf += std::to_string(b);
  buf += solution ? ",solution," : unexplored ? ",unexplored," : ",undecided,";
  buf += std::to_string(c);
  buf += c >= 0 && c < r.filtered ? ",1" : ",0";
  for (int v = 0; v < boxes.nv(); ++v) {
    buf += ',';
    buf += fmt_double(boxes.lo(b, v));
    buf += ',';
    buf += fmt_double(boxes.hi(b, v));
  }
  // Why a box stayed undecided: `constraint` (on the boundary of an additional
  // constraint, the paper's blue boxes) or `singular` (P1 or P2 failed, red and
  // black); empty for solution and unexplored boxes.
  const char* why = solution || unexplored ? ""
                    : r.boxes.kind(b) == UndecidedKind::Constraint ? "constraint"
                                                                          : "singular";
  buf += ',';
  buf += why;
  buf += '\n';
}

}  // namespace

void write_boxes_csv(const Model& m, const AspectsResult& r, const std::string& path) {
  AtomicFile f(path);
  // Written in pieces of about a megabyte: the whole file can take gigabytes.
  std::string buf = header(m);
  for (int b = 0; b < r.boxes.size(); ++b) {
    append_row(r, b, buf);
    if (buf.size() >= (size_t(1) << 20)) {
      f.write(buf);
      buf.clear();
    }
  }
  f.write(buf);
  f.commit();
}

}  // namespace aspects
