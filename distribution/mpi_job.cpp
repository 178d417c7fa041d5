#include "distribution/mpi_job.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace aspects {

namespace {

constexpr int kExitStatusTag = 11;
// MPI counts are ints: a longer message goes in pieces of this size, after its length.
constexpr size_t kPiece = size_t(1) << 30;

// Calls `ready` (under `lock`) until it returns true, sleeping between calls.
template <class F>
void poll(std::mutex& lock, F ready) {
  auto pause = std::chrono::microseconds(20);
  for (;;) {
    {
      std::lock_guard<std::mutex> g(lock);
      if (ready()) return;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(1000));
  }
}

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

MPI_Comm communicator(void* bulk, MpiJob::Channel c) {
  return c == MpiJob::Bulk ? *static_cast<MPI_Comm*>(bulk) : MPI_COMM_WORLD;
}

}  // namespace

MpiJob::MpiJob() {
  int provided = 0;
  check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided), "MPI_Init_thread");
  if (provided < MPI_THREAD_SERIALIZED) {
    MPI_Finalize();
    throw std::runtime_error("this MPI library cannot be called from several threads "
                             "(MPI_THREAD_SERIALIZED), which a distributed solve needs");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  auto* bulk = new MPI_Comm;
  check(MPI_Comm_dup(MPI_COMM_WORLD, bulk), "MPI_Comm_dup");
  bulk_ = bulk;
}

MpiJob::~MpiJob() {
  auto* bulk = static_cast<MPI_Comm*>(bulk_);
  MPI_Comm_free(bulk);
  delete bulk;
  MPI_Finalize();
}

void MpiJob::send(int to, int tag, const std::string& bytes, Channel c) {
  const MPI_Comm comm = communicator(bulk_, c);
  auto send_piece = [&](const void* p, size_t n) {
    MPI_Request req;
    {
      std::lock_guard<std::mutex> g(lock_);
      check(MPI_Isend(p, int(n), MPI_BYTE, to, tag, comm, &req), "MPI_Isend");
    }
    poll(lock_, [&] {
      int done = 0;
      check(MPI_Test(&req, &done, MPI_STATUS_IGNORE), "MPI_Test");
      return done != 0;
    });
  };
  unsigned char length[8];
  const uint64_t n = bytes.size();
  for (int i = 0; i < 8; ++i) length[i] = (n >> (8 * i)) & 0xffu;
  send_piece(length, 8);
  for (size_t at = 0; at < bytes.size(); at += kPiece)
    send_piece(bytes.data() + at, std::min(kPiece, bytes.size() - at));
}

std::string MpiJob::receive(int from, int tag, int* sender, int* found_tag, Channel c) {
  const MPI_Comm comm = communicator(bulk_, c);
  MPI_Status status;
  poll(lock_, [&] {
    int flag = 0;
    check(MPI_Iprobe(from == kAny ? MPI_ANY_SOURCE : from, tag == kAny ? MPI_ANY_TAG : tag,
                     comm, &flag, &status),
          "MPI_Iprobe");
    return flag != 0;
  });
  // The pieces follow the length from the same sender with the same tag, in order.
  const int src = status.MPI_SOURCE, t = status.MPI_TAG;
  auto receive_piece = [&](void* p, size_t n) {
    MPI_Request req;
    {
      std::lock_guard<std::mutex> g(lock_);
      check(MPI_Irecv(p, int(n), MPI_BYTE, src, t, comm, &req), "MPI_Irecv");
    }
    poll(lock_, [&] {
      int done = 0;
      MPI_Status st;
      check(MPI_Test(&req, &done, &st), "MPI_Test");
      if (!done) return false;
      int count = 0;
      MPI_Get_count(&st, MPI_BYTE, &count);
      if (size_t(count) != n) throw std::runtime_error("MPI: a message of an unexpected length");
      return true;
    });
  };
  unsigned char length[8];
  receive_piece(length, 8);
  uint64_t n = 0;
  for (int i = 0; i < 8; ++i) n |= uint64_t(length[i]) << (8 * i);
  std::string bytes(n, '\0');
  for (size_t at = 0; at < n; at += kPiece)
    receive_piece(&bytes[at], std::min(kPiece, size_t(n) - at));
  if (sender) *sender = src;
  if (found_tag) *found_tag = t;
  return bytes;
}

bool MpiJob::probe(int from, int tag, Channel c) {
  const MPI_Comm comm = communicator(bulk_, c);
  std::lock_guard<std::mutex> g(lock_);
  int flag = 0;
  MPI_Status status;
  check(MPI_Iprobe(from == kAny ? MPI_ANY_SOURCE : from, tag == kAny ? MPI_ANY_TAG : tag,
                   comm, &flag, &status),
        "MPI_Iprobe");
  return flag != 0;
}

std::vector<std::string> MpiJob::gather(const std::string& mine) {
  std::vector<char> all(rank_ == 0 ? mine.size() * size_ : 0);
  std::lock_guard<std::mutex> g(lock_);
  check(MPI_Gather(mine.data(), int(mine.size()), MPI_BYTE, all.data(), int(mine.size()),
                   MPI_BYTE, 0, MPI_COMM_WORLD),
        "MPI_Gather");
  std::vector<std::string> out;
  if (rank_ == 0)
    for (int r = 0; r < size_; ++r)
      out.emplace_back(all.data() + r * mine.size(), mine.size());
  return out;
}

std::vector<int> MpiJob::broadcast(std::vector<int> values) {
  std::lock_guard<std::mutex> g(lock_);
  check(MPI_Bcast(values.data(), int(values.size()), MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return values;
}

void MpiJob::finish(int exit_code) {
  if (rank_ != 0) return;
  if (workers_ == WorkerState::Searching) abort(exit_code == 0 ? 1 : exit_code);
  if (workers_ != WorkerState::Waiting) return;
  const std::string status(reinterpret_cast<const char*>(&exit_code), sizeof exit_code);
  for (int r = 1; r < size_; ++r) send(r, kExitStatusTag, status);
  workers_ = WorkerState::Idle;
}

int MpiJob::ranks_on_this_node() const {
  MPI_Comm node;
  check(MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node),
        "MPI_Comm_split_type");
  int n = 1;
  MPI_Comm_size(node, &n);
  MPI_Comm_free(&node);
  return n;
}

int MpiJob::wait_for_exit_status(
    const std::function<void(int tag, const std::string& message)>& other) {
  std::string status;
  for (int tag = -1; tag != kExitStatusTag;) {
    status = receive(0, kAny, nullptr, &tag);
    if (tag != kExitStatusTag && other) other(tag, status);
  }
  int code = 1;
  if (status.size() == sizeof code) std::memcpy(&code, status.data(), sizeof code);
  return code;
}

void MpiJob::abort(int exit_code) {
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::abort();  // MPI_Abort does not return
}

}  // namespace aspects
