#include "run/boxes_csv.h"

#include <charconv>

#include "io/atomic_file.h"

namespace aspects {

namespace {

// The shortest decimal that reads back as x (std::to_chars): exact as %.17g is, and much
// faster; at small eps this file is tens of gigabytes, and its thread was the last of the
// outputs to finish.
void append_double(double x, std::string& buf) {
  char text[32];
  const std::to_chars_result r = std::to_chars(text, text + sizeof text, x);
  buf.append(text, r.ptr);
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
    append_double(boxes.lo(b, v), buf);
    buf += ',';
    append_double(boxes.hi(b, v), buf);
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
