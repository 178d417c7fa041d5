// LinkRecords (proofs/link_records.cpp): the certified links' numbers, spilled to an unnamed
// temporary file past kSpillBytes. Every number must come back exactly, in any read order,
// from memory and from the file alike; a copy must not share the file's future.
//
// Seen failing (each break made in proofs/link_records.cpp, then reverted):
//  - spill() not clearing the tail: SpilledRecordsComeBackExactly and CopiesAreIndependent
//    fail;
//  - the cache's window read from record i instead of its first record: the same two fail;
//  - the copy constructor copying only the tail: CopiesAreIndependent fails;
//  - one cache shared by every thread (as before the per-thread windows):
//    TwoThreadsReadAtOnce crashes (a window resized under the other thread's reads).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>

#include "link.h"

using namespace aspects;

namespace {

constexpr int kN = 3;

// Record i: every number distinct, exactly representable, and not all small integers.
double value(size_t i, int k) { return double(i) * 64.0 + k + 0.015625 * (k + 1); }

LinkProof proof(size_t i) {
  LinkProof p;
  for (int j = 0; j < kN; ++j) p.witness.push_back(value(i, j));
  for (int j = 0; j < kN; ++j)
    p.existence.inflated.emplace_back(value(i, kN + 2 * j), value(i, kN + 2 * j + 1));
  for (int k = 0; k < kN * kN; ++k) p.existence.C.push_back(value(i, 3 * kN + k));
  return p;
}

void expect_record(const LinkRecords& r, size_t i) {
  for (int j = 0; j < kN; ++j) ASSERT_EQ(r.witness(i)[j], value(i, j)) << "record " << i;
  for (int j = 0; j < kN; ++j) {
    ASSERT_EQ(r.inflated_lo(i, j), value(i, kN + 2 * j)) << "record " << i;
    ASSERT_EQ(r.inflated_hi(i, j), value(i, kN + 2 * j + 1)) << "record " << i;
  }
  for (int k = 0; k < kN * kN; ++k) ASSERT_EQ(r.C(i)[k], value(i, 3 * kN + k)) << "record " << i;
}

// Records 0 .. count-1, as the link phase makes them: pushed into blocks, appended one by one.
LinkRecords make(size_t count) {
  LinkRecords all(kN);
  LinkRecords block(kN);
  for (size_t i = 0; i < count; ++i) {
    block.push(proof(i));
    all.append_one(block, block.size() - 1);
  }
  return all;
}

// A spill happens when the tail reaches kSpillBytes.
const size_t kRecordBytes = sizeof(double) * (3 * kN + kN * kN);
const size_t kPerSpill = (LinkRecords::kSpillBytes + kRecordBytes - 1) / kRecordBytes;

}  // namespace

TEST(LinkRecords, SpilledRecordsComeBackExactly) {
  const size_t count = 2 * kPerSpill + kPerSpill / 3;  // two spills and a tail in memory
  LinkRecords r = make(count);
  ASSERT_EQ(r.size(), count);
  ASSERT_EQ(r.spilled(), 2 * kPerSpill);
  for (size_t i = 0; i < count; ++i) expect_record(r, i);
  for (size_t i = count; i-- > 0;) expect_record(r, i);
  std::mt19937_64 rng(7);
  for (int t = 0; t < 5000; ++t) expect_record(r, rng() % count);
  EXPECT_THROW(r.witness(count), std::out_of_range);
}

// The certificate writer and the result index read the same records at once
// (run/solve_outputs.cpp): each thread must get its own numbers, whatever the other reads.
TEST(LinkRecords, TwoThreadsReadAtOnce) {
  const size_t count = 3 * kPerSpill;
  const LinkRecords r = make(count);
  ASSERT_EQ(r.spilled(), 3 * kPerSpill);
  std::atomic<long> wrong{0};
  const auto read = [&](bool backward) {
    for (int pass = 0; pass < 4; ++pass)
      for (size_t k = 0; k < count; ++k) {
        const size_t i = backward ? count - 1 - k : k;
        const double* w = r.witness(i);
        for (int j = 0; j < kN; ++j) wrong += w[j] != value(i, j);
      }
  };
  std::thread other(read, true);
  read(false);
  other.join();
  EXPECT_EQ(wrong.load(), 0);
}

TEST(LinkRecords, SmallSetsStayInMemory) {
  LinkRecords r = make(kPerSpill - 1);
  EXPECT_EQ(r.spilled(), 0u);
  for (size_t i = 0; i < r.size(); i += 97) expect_record(r, i);
}

TEST(LinkRecords, CopiesAreIndependent) {
  LinkRecords a = make(kPerSpill + 10);
  ASSERT_GT(a.spilled(), 0u);
  LinkRecords b = a;
  LinkRecords block(kN);
  for (size_t i = 0; i < kPerSpill; ++i) {  // a spills again, where b's file would continue
    block.push(proof(1000000 + i));
    a.append_one(block, i);
  }
  ASSERT_EQ(b.size(), kPerSpill + 10);
  for (size_t i = 0; i < b.size(); ++i) expect_record(b, i);
  LinkRecords c = std::move(a);
  EXPECT_EQ(a.size(), 0u);
  ASSERT_EQ(c.size(), 2 * kPerSpill + 10);
  expect_record(c, 5);
}

TEST(LinkRecords, NoTemporaryDirectoryIsAClearError) {
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  setenv("TMPDIR", "/nonexistent/aspects-test", 1);
  try {
    make(kPerSpill + 1);
    ADD_FAILURE() << "spilled without a temporary directory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot create a temporary file"), std::string::npos)
        << e.what();
  }
  if (old) setenv("TMPDIR", saved.c_str(), 1);
  else unsetenv("TMPDIR");
}
