#include "count_certificate.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "numerics/interval.h"

namespace aspects {

namespace {

// The records of one certificate line by line, reals as printf("%a") prints them.
class Lines {
 public:
  explicit Lines(std::string& out) : out_(out) {}
  Lines& word(const std::string& w) {
    if (!at_start_) out_ += ' ';
    out_ += w;
    at_start_ = false;
    return *this;
  }
  Lines& integer(long k) { return word(std::to_string(k)); }
  Lines& real(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%a", x);
    return word(buf);
  }
  Lines& reals(const std::vector<double>& xs) {
    for (double x : xs) real(x);
    return *this;
  }
  void end() {
    out_ += '\n';
    at_start_ = true;
    ++records_;
  }
  long records() const { return records_; }
  void count_existing(long k) { records_ += k; }

 private:
  std::string& out_;
  bool at_start_ = true;
  long records_ = 0;
};

std::string signs_of(uint32_t cls, int p) {
  if (p == 0) return ".";
  std::string s;
  for (int i = 0; i < p; ++i) s += (cls >> i) & 1 ? '+' : '-';
  return s;
}

const char* empty_word(CountCellRecord::EmptyBy e) {
  switch (e) {
    case CountCellRecord::Signs: return "signs";
    case CountCellRecord::NoPoint: return "void";
    case CountCellRecord::Paving: return "paving";
    case CountCellRecord::OtherClass: return "other-class";
    case CountCellRecord::Constraint: return "constraint";
    case CountCellRecord::NotEmpty: break;
  }
  return "?";
}

}  // namespace

CountCertificateWriter::CountCertificateWriter(const std::string& path, const Model& model,
                                               double eps)
    : path_(path), first_path_(path + ".first-cover"), model_(model) {
  first_.reset(new CertificateWriter(first_path_, model, long(working_precision()),
                                     AspectsConfig().tau, eps));
}

CountCertificateWriter::~CountCertificateWriter() {
  first_.reset();
  if (first_done_) std::remove(first_path_.c_str());
}

void CountCertificateWriter::first_cover_done(const AspectsResult& solved, void* self) {
  auto* w = static_cast<CountCertificateWriter*>(self);
  w->first_->finish(w->model_, solved);
  w->first_done_ = true;
}

void CountCertificateWriter::finish(const Model&, const CountResult& r) {
  if (!first_done_ || !r.records)
    throw std::runtime_error("count certificate: the count stopped before its first cover");
  const CountRecords& rec = *r.records;
  // The first cover's header and tree, its first line naming the count format.
  std::ifstream in(first_path_, std::ios::binary);
  std::string text, l;
  std::getline(in, l);  // aspects-certificate 2
  text = "aspects-count-certificate 1\n";
  std::getline(in, l);  // tool
  text += l + '\n';
  std::getline(in, l);  // model BYTES SHA
  text += l + '\n';
  long bytes = std::stol(l.substr(6, l.find(' ', 6) - 6));
  std::string model_text(size_t(bytes) + 1, '\0');
  in.read(&model_text[0], bytes + 1);
  text += model_text;
  bool tree_ended = false;
  long lines = 3;
  for (char c : model_text) lines += c == '\n';
  while (std::getline(in, l)) {
    text += l + '\n';
    ++lines;
    if (l.compare(0, 9, "end-tree ") == 0) {
      tree_ended = true;
      break;
    }
  }
  if (!tree_ended) throw std::runtime_error("count certificate: no tree in " + first_path_);
  Lines out(text);
  out.count_existing(lines);
  const int p = int(r.factor_text.size());
  out.word("count").integer(long(rec.cells.size())).integer(rec.first_cover).end();
  for (size_t id = 0; id < rec.cells.size(); ++id) {
    const CountCellRecord& c = rec.cells[id];
    if (long(id) >= rec.first_cover) out.word("half").integer(long(id)).reals(c.origin).end();
    switch (c.fit) {
      case CountCellRecord::NoFit: break;
      case CountCellRecord::Charted:
      case CountCellRecord::Void:
        out.word(c.fit == CountCellRecord::Charted ? "fit" : "void").integer(long(id));
        for (int w : c.w) out.integer(w);
        out.reals(c.w_tilde);
        if (c.fit == CountCellRecord::Charted) out.reals(c.box);
        out.end();
        break;
      case CountCellRecord::NoSolution: out.word("none").integer(long(id)).end(); break;
    }
    if (!c.alive) {
      out.word("split").integer(long(id)).integer(c.split_var).real(c.split_at);
      out.integer(c.child[0]).integer(c.child[1]).end();
      continue;
    }
    for (const CountCellRecord::Piece& q : c.pieces) {
      out.word("piece").integer(long(id)).word(signs_of(q.cls, p)).word(piece_state_name(q.state));
      if (q.state == PieceState::Empty) {
        out.word(empty_word(q.empty_by));
        out.end();
        continue;
      }
      out.word(q.state != PieceState::Connected       ? "-"
               : q.connected_by == CountCellRecord::Star ? "star"
                                                         : "graph");
      if (!q.point_u.empty()) {
        out.word("point");
        for (int w : q.point_w) out.integer(w);
        out.reals(q.point_u).reals(q.point_hint);
      } else {
        out.word("-");
      }
      out.end();
    }
  }
  for (const CountRecords::Refuted& e : rec.refuted)
    out.word("refuted").integer(e.a).integer(e.b).word(signs_of(e.cls, p)).end();
  for (const CountRecords::Joined& e : rec.joined) {
    out.word("joined").integer(e.a).integer(e.b).word(signs_of(e.cls, p));
    std::string shift;
    for (int k : e.shift) shift += "-0+"[k + 1];
    out.word(shift).word(e.bridge ? "bridge" : "point");
    for (int w : e.w) out.integer(w);
    if (e.bridge) out.reals(e.w_tilde);
    else out.reals(e.u).reals(e.hint);
    out.end();
  }
  out.word("claim").word("count-lower").integer(r.bounds.lower).end();
  out.word("claim").word("count-upper");
  if (r.bounds.upper >= 0) out.integer(r.bounds.upper);
  else out.word("none");
  out.end();
  out.word("end").integer(out.records()).end();
  AtomicFile file(path_);
  file.write(text);
  file.commit();
}

}  // namespace aspects
