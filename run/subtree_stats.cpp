#include "run/subtree_stats.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "io/atomic_file.h"
#include "io/le_reader.h"
#include "io/le_writer.h"
#include "pipeline/remote_subtrees.h"
#include "run/search_part_codec.h"

namespace aspects {

namespace {

class StringWriter : public LeWriter {
 public:
  void bytes(const void* p, size_t n) override { s.append(static_cast<const char*>(p), n); }
  std::string s;
};

class PartReader : public LeReader {
 public:
  explicit PartReader(const std::string& b) : LeReader(b, b.size()) {}
  [[noreturn]] void fail(const std::string& why) const override {
    throw std::logic_error("--subtree-stats: a part's encoding does not read back: " + why);
  }
};

// The part's bytes in a message, and the seconds to read them back (rank 0's cost);
// `deferred`: the subtrees its Deferred leaves may name (the top's; 0 for a subtree).
std::pair<long, double> encode_and_decode(const SearchPart& part, size_t deferred) {
  StringWriter w;
  const uint32_t p = uint32_t(part.boxes.factors());
  write_search_part(w, part, p);
  const auto start = std::chrono::steady_clock::now();
  PartReader in(w.s);
  SearchPart back;
  read_search_part(in, back, uint32_t(part.boxes.nv()), p, uint32_t(deferred));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {long(w.s.size()), seconds};
}

// The message of mpi_subtrees.cpp: kind u8, task i32, five u64 counts, the part, u8 held,
// u64 record count, then the records (or, held, in a later message).
constexpr long kMessageOverhead = 1 + 4 + 5 * 8 + 1 + 8;

std::string seconds_text(double s) {
  if (s < 0) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%.6f", s);
  return b;
}

}  // namespace

void SubtreeStats::attach(AspectsConfig& cfg) {
  cfg.subtree_observer.top_searched = [this](const SearchState& st, const PartWork& work) {
    top_searched(st, work);
  };
  cfg.subtree_observer.searched_here = [this](int32_t k, const SearchPart& part,
                                              const PartWork& work) {
    part_done(k, part, &work, -1);
  };
  cfg.subtree_observer.returned = [this](int32_t k, const ReturnedPart& part, size_t records) {
    if (part.bytes.empty()) return part_done(k, part.part, nullptr, long(records));
    // Decoded here only for its counts (the run decodes it at the merge).
    PartReader in(part.bytes);
    SearchPart decoded;
    read_search_part(in, decoded, nv_, p_, 0);
    part_done(k, decoded, nullptr, long(records));
  };
}

void SubtreeStats::top_searched(const SearchState& st, const PartWork& work) {
  std::lock_guard<std::mutex> g(lock_);
  nv_ = uint32_t(st.top.boxes.nv());
  p_ = uint32_t(st.top.boxes.factors());
  top_.nodes = long(st.top.tree.size() - st.deferred.size());  // its leaves are their roots
  top_.output_boxes = st.top.boxes.size();
  top_.cpu_seconds = work.cpu_seconds;
  top_.wall_seconds = work.wall_seconds;
  std::tie(top_.part_bytes, top_.decode_seconds) = encode_and_decode(st.top, st.deferred.size());
  subtrees_.assign(st.deferred.size(), Row());
  // Depth first from the root, each node's path with it; a deferred leaf names its task.
  std::vector<std::pair<int32_t, std::string>> stack{{0, ""}};
  while (!stack.empty()) {
    auto [node, path] = std::move(stack.back());
    stack.pop_back();
    const SearchNode& n = st.top.tree[size_t(node)];
    if (n.fate != LeafFate::Deferred || n.internal()) {
      if (levels_.size() <= path.size()) levels_.resize(path.size() + 1);
      Row& level = levels_[path.size()];
      level.depth = int(path.size());
      level.nodes = std::max(0L, level.nodes) + 1;
      level.output_boxes += n.leaf() >= 0;
    }
    if (n.internal()) {
      stack.push_back({n.right(), path + "1"});
      stack.push_back({n.left(), path + "0"});
    } else if (n.fate == LeafFate::Deferred) {
      Row& r = subtrees_.at(size_t(n.index));
      r.depth = int(path.size());
      r.path = path;
    }
  }
}

void SubtreeStats::part_done(int32_t k, const SearchPart& part, const PartWork* work,
                             long records) {
  auto [bytes, decode] = encode_and_decode(part, 0);  // outside the lock: threads overlap
  std::lock_guard<std::mutex> g(lock_);
  Row& r = subtrees_.at(size_t(k));
  r.nodes = long(part.tree.size());
  r.output_boxes = part.boxes.size();
  if (work) {
    r.cpu_seconds = work->cpu_seconds;
    r.wall_seconds = work->wall_seconds;
  } else {
    r.message_bytes = kMessageOverhead + bytes + records;
  }
  r.part_bytes = bytes;
  r.decode_seconds = decode;
}

void SubtreeStats::write() const {
  std::ostringstream out;
  out << "part,task,depth,path,nodes,output_boxes,cpu_seconds,wall_seconds,part_bytes,"
         "decode_seconds,message_bytes,searched_by\n";
  // A level's boxes were searched with the top: it has no clock, bytes or searcher.
  auto row = [&](const char* part, long task, const Row& r) {
    if (part == std::string("level")) {
      out << part << ",-1," << r.depth << ",," << r.nodes << ',' << r.output_boxes
          << ",,,,,,\n";
      return;
    }
    out << part << ',' << task << ',' << r.depth << ',' << r.path << ',';
    if (r.nodes >= 0) out << r.nodes;
    out << ',' << r.output_boxes << ',' << seconds_text(r.cpu_seconds) << ','
        << seconds_text(r.wall_seconds) << ',' << r.part_bytes << ','
        << seconds_text(r.decode_seconds) << ',';
    if (r.message_bytes >= 0) out << r.message_bytes;
    out << ',' << (r.nodes < 0 ? "" : r.message_bytes >= 0 ? "remote" : "here") << '\n';
  };
  row("top", -1, top_);
  for (const Row& level : levels_) row("level", -1, level);
  for (size_t k = 0; k < subtrees_.size(); ++k) row("subtree", long(k), subtrees_[k]);
  write_file_atomically(path_, out.str());
}

}  // namespace aspects
