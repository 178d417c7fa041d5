#include "distribution/mpi_subtrees.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <future>
#include <iostream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <thread>
#include <tuple>

#include "certificate_writer.h"
#include "distribution/mpi_held_records.h"
#include "distribution/mpi_message.h"
#include "distribution/mpi_stop.h"
#include "model/determinant_factors.h"
#include "pipeline/parallel.h"
#include "pipeline/search_phase.h"
#include "run/search_part_codec.h"

namespace aspects {

namespace {

constexpr int kRankDone = 10;
constexpr int kStop = 13;
constexpr int kFetchRecords = 14;  // Control: rank 0 asks for a subtree's held records
constexpr int kHeldRecords = 15;   // Bulk: the answer
constexpr int kFromThread = 1000;
constexpr int kToThread = 3000;
constexpr int kMaxThreads = 1024;  // --threads' limit
constexpr uint8_t kReady = 0;                   // a request
constexpr uint8_t kComplete = 1, kStopped = 2;  // parts

std::string task_message(int32_t task, const std::vector<DeferredSubtree>& deferred,
                         bool hold_records) {
  MessageWriter w;
  w.i32(task);
  if (task < 0) return w.s;
  w.u8(hold_records);
  const DeferredSubtree& d = deferred[task];
  w.i32(d.parent_split);
  for (const Interval& x : d.box) {
    w.f64(x.lo_down());
    w.f64(x.hi_up());
  }
  return w.s;
}

// This rank's file for the records of the subtree a thread searches (local disk).
std::string records_path(int rank, int thread) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/aspects-rank" + std::to_string(rank) +
         "-" + std::to_string(getpid()) + "-thread" + std::to_string(thread) + ".records";
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw std::runtime_error("cannot read " + path);
  return b;
}

}  // namespace

int defer_depth_for(int processes, int threads) {
  const double subtrees = 256.0 * std::max(1, processes) * std::max(1, threads);
  return std::max(8, int(std::ceil(std::log2(subtrees))));
}

void MpiSubtreeServer::serve(SubtreeQueue& queue, const std::vector<DeferredSubtree>& deferred,
                             int /*factors*/, const std::function<bool()>& stopped,
                             const Returned& returned, bool records_may_wait) {
  if (deferred.size() < size_t(job_.size()) && !stopped())  // a stopped top left the rest
    std::cerr << "aspects: note: the search left " << deferred.size() << " subtrees for "
              << job_.size() << " processes: some will have nothing to search (fewer "
              << "processes, or a smaller --eps, keeps them busy)\n";
  source_.assign(deferred.size(), -1);
  // The subtrees given whose parts have not come back yet: a part must answer one of them.
  // A thread holds two at most: the one it searches and the next, asked for in advance.
  std::set<std::tuple<int, int, int32_t>> owed;
  // Once this process stops, the ranks searching a subtree are told to stop it (the others
  // get no more subtrees).
  bool told = false;
  auto tell_stop = [&] {
    std::vector<uint8_t> searching(job_.size(), 0);
    for (const auto& [rank, thread, task] : owed) searching[rank] = 1;
    for (int r = 1; r < job_.size(); ++r)
      if (searching[r]) job_.send(r, kStop, std::string());
    told = true;
  };
  // Requests first: a rank's thread waits for its next subtree, not for its part's intake.
  auto answer_request = [&] {
    int sender = 0, tag = 0;
    const std::string msg = job_.receive(MpiJob::kAny, MpiJob::kAny, &sender, &tag);
    if (tag == kRankDone) return true;
    const int thread = tag - kFromThread;
    MessageReader in(msg, sender);
    if (thread < 0 || thread >= kMaxThreads) in.fail("unexpected tag " + std::to_string(tag));
    if (in.u8() != kReady || !in.at_end()) in.fail("unexpected message");
    const int32_t next = stopped() ? -1 : queue.claim();
    if (next >= 0) owed.insert({sender, thread, next});
    job_.send(sender, kToThread + thread, task_message(next, deferred, records_may_wait));
    return false;
  };
  // Kept as the bytes it came in: decode() reads it as the merge grafts it.
  auto take_part = [&] {
    int sender = 0, tag = 0;
    const std::string msg =
        job_.receive(MpiJob::kAny, MpiJob::kAny, &sender, &tag, MpiJob::Bulk);
    MessageReader in(msg, sender);
    const uint8_t kind = in.u8();
    if (kind != kComplete && kind != kStopped) in.fail("unexpected part");
    const int32_t task = in.i32();
    if (owed.erase({sender, tag - kFromThread, task}) != 1) in.fail("a subtree it was not given");
    ReturnedPart part;
    for (long* x : {&part.nodes, &part.solutions, &part.undecided, &part.discarded, &part.boxes})
      *x = long(in.i64());
    if (part.nodes < 0 || part.boxes < 0) in.fail("bad counts");
    const uint64_t part_bytes = in.u64();
    if (part_bytes > in.left()) in.fail("truncated");
    part.bytes.reserve(8 + part_bytes);
    part.bytes.append(msg, in.pos() - 8, 8 + part_bytes);  // its length, then its bytes
    in.view(part_bytes);
    const uint8_t held = in.u8();
    if (held > 1 || (held && !records_may_wait)) in.fail("unexpected records");
    part.record_bytes = in.u64();
    std::string records;
    if (held) {
      held_[task] = {sender, part.record_bytes};
      part.fetch_records = [this, task] { return fetch_records(task); };
    } else {
      records = in.bytes(part.record_bytes);
    }
    if (!in.at_end()) in.fail("trailing bytes");
    source_.at(size_t(task)) = sender;
    returned(task, kind == kComplete ? PartOutcome::Complete : PartOutcome::Stopped,
             std::move(part), std::move(records));
  };
  int done = 0;
  auto pause = std::chrono::microseconds(20);
  while (done < job_.size() - 1 || !owed.empty()) {
    if (!told && stopped()) tell_stop();
    if (job_.probe(MpiJob::kAny, MpiJob::kAny)) {
      done += answer_request();
    } else if (job_.probe(MpiJob::kAny, MpiJob::kAny, MpiJob::Bulk)) {
      take_part();
    } else {
      std::this_thread::sleep_for(pause);
      pause = std::min(pause * 2, std::chrono::microseconds(1000));
      continue;
    }
    pause = std::chrono::microseconds(20);
  }
  job_.set_workers(WorkerState::Waiting);
}

// A request and its answer cost a poll of each rank's waiting loop (up to a ms each), and a
// subtree's records can be small (kilobytes): a rank is asked for the records of its next
// subtrees in the order the certificate splices them (by task), up to kFetchBatch bytes,
// and sends them in one message.
std::string MpiSubtreeServer::fetch_records(int32_t task) {
  const auto it = held_.find(task);
  if (it == held_.end()) throw std::logic_error("no held records for this subtree");
  const int rank = it->second.rank;
  if (!fetched_.count(task)) {
    MessageWriter ask;
    std::vector<int32_t> batch;
    uint64_t bytes = 0;
    for (auto next = it; next != held_.end() && (batch.empty() || bytes < kFetchBatch); ++next)
      if (next->second.rank == rank) {
        batch.push_back(next->first);
        bytes += next->second.size;
      }
    ask.u32(uint32_t(batch.size()));
    for (int32_t t : batch) ask.i32(t);
    job_.send(rank, kFetchRecords, ask.s);
    const std::string msg = job_.receive(rank, kHeldRecords, nullptr, nullptr, MpiJob::Bulk);
    MessageReader in(msg, rank);
    if (in.u32() != batch.size()) in.fail("records it was not asked for");
    for (int32_t t : batch) {
      if (in.i32() != t) in.fail("records it was not asked for");
      const uint64_t size = held_.at(t).size;
      if (in.u64() != size) in.fail("records of another size than its part said");
      fetched_[t] = in.bytes(size);
    }
    if (!in.at_end()) in.fail("trailing bytes");
  }
  std::string records = std::move(fetched_.at(task));
  fetched_.erase(task);
  held_.erase(it);
  return records;
}

void MpiSubtreeServer::decode(int32_t task, const std::string& bytes, int factors,
                              SearchPart& part) const {
  MessageReader in(bytes, source_.at(size_t(task)));
  read_search_part(in, part, uint32_t(nv_), uint32_t(factors), 0);
  if (!in.at_end()) in.fail("trailing bytes");
}

void search_subtrees_for_rank0(MpiJob& job, Model& model, const AspectsConfig& given,
                               HeldRecords* held) {
  const bool certificate = held != nullptr;
  RankStop stop(job, kStop);
  AspectsConfig config = given;
  config.stop = &stop.condition();
  const std::vector<Factor> factors = determinant_factors(model);
  const int nv = int(model.vars.size()), threads = std::max(1, config.threads);
  const long prec = working_precision();
  Parallel parallel(threads, prec);
  parallel.arena().execute([&] {
    tbb::parallel_for(0, threads, [&](int thread) {
      set_working_precision(prec);  // MPFR's default precision is per thread
      MessageWriter ready;
      ready.u8(kReady);
      // The next subtree is asked for before this one is searched: its answer is there
      // when the search ends, instead of a round trip (and rank 0's polling) between two.
      bool hold = false;  // this subtree's records stay here until rank 0 fetches them
      auto next_subtree = [&](DeferredSubtree& subtree) {
        const std::string msg = job.receive(0, kToThread + thread);
        MessageReader in(msg, 0);
        const int32_t task = in.i32();
        if (task < 0) return task;
        const uint8_t h = in.u8();
        if (h > 1) in.fail("bad message");
        hold = h;
        subtree.parent_split = in.i32();
        subtree.node = -1;
        subtree.box.resize(nv);
        for (Interval& x : subtree.box) {
          const double lo = in.f64_bits(), hi = in.f64_bits();
          if (!(lo <= hi)) in.fail("bad box");
          x.set_hull(lo, hi);
        }
        if (!in.at_end()) in.fail("trailing bytes");
        return task;
      };
      std::future<void> sending;  // the last part's send
      DeferredSubtree subtree;
      job.send(0, kFromThread + thread, ready.s);
      for (int32_t task = next_subtree(subtree); task >= 0; task = next_subtree(subtree)) {
        job.send(0, kFromThread + thread, ready.s);
        SearchPart part;
        std::string records;
        bool complete;
        if (certificate) {
          const int p = int(factors.size());
          TreeRecordFile sink(records_path(job.rank(), thread), p, model.n(),
                              config.grid_records ? compact_tree(subtree.box, model, p) : nullptr);
          complete = search_subtree(model, config, factors, subtree, part, &sink);
          records = read_file(sink.path());
        } else {
          complete = search_subtree(model, config, factors, subtree, part, nullptr);
        }
        MessageWriter out;
        out.u8(complete ? kComplete : kStopped);
        out.i32(task);
        ReturnedPart counts;
        count_leaves(part, counts);
        for (long x :
             {counts.nodes, counts.solutions, counts.undecided, counts.discarded, counts.boxes})
          out.i64(x);
        write_search_part(out, part, uint32_t(factors.size()));
        const bool keep = hold && certificate;
        out.u8(keep);
        out.u64(records.size());
        if (keep)
          held->keep(task, records);
        else
          out.bytes(records.data(), records.size());
        // The part travels while this thread searches its next subtree; one at a time, so
        // that a rank 0 slow to take parts in holds the thread back.
        if (sending.valid()) sending.get();
        sending = std::async(std::launch::async, [&job, thread, m = std::move(out.s)] {
          job.send(0, kFromThread + thread, m, MpiJob::Bulk);
        });
      }
      if (sending.valid()) sending.get();
    }, tbb::simple_partitioner());
  });
  job.send(0, kRankDone, std::string());
}

int serve_held_records_until_exit(MpiJob& job, const HeldRecords* held) {
  return job.wait_for_exit_status([&](int tag, const std::string& msg) {
    if (tag != kFetchRecords) return;  // a stop that came after this rank was done
    if (!held) throw std::runtime_error("rank 0 asked for records, and this rank kept none");
    MessageReader in(msg, 0);
    const uint32_t count = in.count(4);
    std::vector<std::pair<int32_t, uint64_t>> tasks(count);  // task, size of its records
    size_t bytes = 4;
    for (auto& [task, size] : tasks) {
      task = in.i32();
      size = held->size(task);
      bytes += 12 + size;
    }
    if (!in.at_end()) in.fail("trailing bytes");
    MessageWriter out;
    out.s.reserve(bytes);  // up to 16 MB: read straight into the message
    out.u32(count);
    for (const auto& [task, size] : tasks) {
      out.i32(task);
      out.u64(size);
      held->append_to(task, out.s);
    }
    job.send(0, kHeldRecords, out.s, MpiJob::Bulk);
  });
}

}  // namespace aspects
