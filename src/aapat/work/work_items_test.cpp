#include "aapat/work/work_items.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <atomic>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "aapat/core/geometry.h"
#include "aapat/work/byte_codec.h"
#include "aapat/work/checkpoint.h"

namespace aapat {
namespace {

std::string square(int i) {
  ByteWriter w;
  w.put<int64_t>(int64_t{i} * i).put_text(std::to_string(i));
  return w.take();
}

// An engine that runs the items itself, one after another, and counts them.
class CountingEngine final : public WorkEngine {
 public:
  void run(std::vector<std::optional<std::string>>& results, const ItemWork& work,
           const Finished& finished) override {
    for (size_t i = 0; i < results.size(); ++i)
      if (!results[i]) {
        results[i] = work(static_cast<int>(i));
        ++ran;
        finished(static_cast<int>(i), *results[i]);
      }
  }
  int ran = 0;
};

std::string temporary_path(const std::string& name) {
  const auto path =
      std::filesystem::temp_directory_path() /
      ("aapat-" + name + "-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::remove(path);
  return path.string();
}

RC_GTEST_PROP(ByteCodec, RoundTripsNumbersTextAndVectorsBitForBit,
              (double x, int32_t n, std::string text, std::vector<double> values)) {
  ByteWriter w;
  w.put(x).put(n).put_text(text).put_all(values);
  const std::string bytes = w.take();
  ByteReader r(bytes);
  const double y = r.get<double>();
  RC_ASSERT(std::memcmp(&x, &y, sizeof x) == 0);  // NaN payloads and -0 too
  RC_ASSERT(r.get<int32_t>() == n);
  RC_ASSERT(r.get_text() == text);
  const std::vector<double> back = r.get_all<double>();
  RC_ASSERT(back.size() == values.size());
  for (size_t i = 0; i < values.size(); ++i)
    RC_ASSERT(std::memcmp(&back[i], &values[i], sizeof(double)) == 0);
  r.finish();
}

TEST(ByteCodec, ShortOrLongResultsAreErrors) {
  ByteWriter w;
  w.put<double>(1.0);
  const std::string bytes = w.take();
  ByteReader shorter(std::string_view(bytes).substr(0, 5));
  EXPECT_THROW(shorter.get<double>(), Error);
  ByteReader longer(bytes);
  EXPECT_THROW(longer.finish(), Error);
  ByteWriter huge;
  huge.put<uint64_t>(uint64_t{1} << 60);
  const std::string claim = huge.take();
  ByteReader vector_claim(claim);
  EXPECT_THROW(vector_claim.get_all<double>(), Error);
}

TEST(WorkItems, ResultsComeInItemOrderWhateverTheEngine) {
  const auto local = run_work_items(1000, square);
  ASSERT_EQ(local.size(), 1000u);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(local[static_cast<size_t>(i)], square(i));
  CountingEngine engine;
  const WorkSession session(engine, nullptr);
  EXPECT_EQ(run_work_items(1000, square), local);
  EXPECT_EQ(engine.ran, 1000);
}

TEST(WorkItems, ProgressCountsEveryItemOnce) {
  int calls = 0, last = 0;
  run_work_items(257, square, [&](int done, int total, const std::string& result) {
    ++calls;
    last = done;
    EXPECT_EQ(total, 257);
    EXPECT_FALSE(result.empty());
  });
  EXPECT_EQ(calls, 257);
  EXPECT_EQ(last, 257);
}

TEST(WorkItems, TheLowestFailingItemsErrorIsThrown) {
  try {
    run_work_items(64, [&](int i) -> std::string {
      if (i == 7 || i == 40) throw ParameterError("item", " " + std::to_string(i));
      return square(i);
    });
    FAIL() << "no error";
  } catch (const ParameterError& e) {  // the type survives
    // Item 40 may or may not have run (a failure starts nothing past it);
    // item 7's error wins either way.
    EXPECT_STREQ(e.what(), "item 7");
  }
  EXPECT_THROW(run_work_items(-1, square), Error);
}

TEST(WorkItems, CallsInsideAnItemRunLocally) {
  CountingEngine engine;
  const WorkSession session(engine, nullptr);
  const auto outer = run_work_items(4, [](int i) {
    const auto inner = run_work_items(3, square);  // not through the engine
    return inner[static_cast<size_t>(i % 3)];
  });
  EXPECT_EQ(engine.ran, 4);
  EXPECT_EQ(outer[3], square(0));
}

TEST(Checkpoint, AResumedRunRecomputesOnlyTheMissingItems) {
  const std::string path = temporary_path("checkpoint");
  std::vector<std::string> first, second;
  {
    Checkpoint checkpoint(path, "aapat test --seed 1");
    CountingEngine engine;
    const WorkSession session(engine, &checkpoint);
    first = run_work_items(10, square);
    run_work_items(5, square);
    EXPECT_EQ(engine.ran, 15);
  }
  {
    Checkpoint checkpoint(path, "aapat test --seed 1");
    EXPECT_EQ(checkpoint.restored(), 15);
    CountingEngine engine;
    const WorkSession session(engine, &checkpoint);
    second = run_work_items(10, square);
    run_work_items(5, square);
    run_work_items(3, square);  // a call the first run never made
    EXPECT_EQ(engine.ran, 3);
  }
  EXPECT_EQ(first, second);
  std::filesystem::remove(path);
}

TEST(Checkpoint, ARunThatTakesAnotherPathIsRefusedNotFedWrongResults) {
  const std::string path = temporary_path("path");
  {
    Checkpoint checkpoint(path, "cmd");
    CountingEngine engine;
    const WorkSession session(engine, &checkpoint);
    run_work_items(10, square);
  }
  Checkpoint checkpoint(path, "cmd");
  CountingEngine engine;
  const WorkSession session(engine, &checkpoint);
  EXPECT_THROW(run_work_items(12, square), Error);  // set 1 had 10 items
  std::filesystem::remove(path);
}

TEST(WorkItems, AnEmptyResultIsNotKeptInTheCheckpoint) {
  const std::string path = temporary_path("empty");
  const auto skip_odd = [](int i) { return i % 2 ? std::string() : square(i); };
  {
    Checkpoint checkpoint(path, "cmd");
    CountingEngine engine;
    const WorkSession session(engine, &checkpoint);
    run_work_items(6, skip_odd);
  }
  Checkpoint checkpoint(path, "cmd");
  EXPECT_EQ(checkpoint.restored(), 3);
  CountingEngine engine;
  const WorkSession session(engine, &checkpoint);
  run_work_items(6, skip_odd);
  EXPECT_EQ(engine.ran, 3);  // the odd ones run again
  std::filesystem::remove(path);
}

TEST(Checkpoint, ARecordCutOffByAKillIsDroppedAndRecomputed) {
  const std::string path = temporary_path("cut");
  {
    Checkpoint checkpoint(path, "cmd");
    checkpoint.record(0, 0, square(0));
    checkpoint.record(0, 1, square(1));
  }
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 3);
  {
    Checkpoint checkpoint(path, "cmd");
    EXPECT_EQ(checkpoint.restored(), 1);
    EXPECT_EQ(checkpoint.find(0, 0), square(0));
    EXPECT_FALSE(checkpoint.find(0, 1));
    checkpoint.record(0, 1, square(1));  // appended after the last whole record
  }
  Checkpoint again(path, "cmd");
  EXPECT_EQ(again.restored(), 2);
  EXPECT_EQ(again.find(0, 1), square(1));
  std::filesystem::remove(path);
}

// A record's checksum covers its set and index: two records with their
// indices swapped (or any index edited) are dropped and recomputed, never
// resumed with each other's values.
TEST(Checkpoint, SwappedRecordIndicesAreNotResumed) {
  const std::string path = temporary_path("swapped");
  {
    Checkpoint checkpoint(path, "cmd");
    checkpoint.record(0, 3, square(3));
    checkpoint.record(0, 4, square(4));
  }
  std::string data;
  {
    std::ifstream in(path, std::ios::binary);
    data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const size_t three = data.find("item 0 3 "), four = data.find("item 0 4 ");
  ASSERT_NE(three, std::string::npos);
  ASSERT_NE(four, std::string::npos);
  data[three + 7] = '4', data[four + 7] = '3';
  std::ofstream(path, std::ios::binary | std::ios::trunc) << data;
  Checkpoint checkpoint(path, "cmd");
  EXPECT_EQ(checkpoint.restored(), 0);
  EXPECT_FALSE(checkpoint.find(0, 3));
  EXPECT_FALSE(checkpoint.find(0, 4));
  std::filesystem::remove(path);
}

TEST(Checkpoint, AnotherCommandsFileOrAnyOtherFileIsRefused) {
  const std::string path = temporary_path("other");
  { Checkpoint checkpoint(path, "aapat optimize --seed 1"); }
  try {
    Checkpoint checkpoint(path, "aapat optimize --seed 2");
    FAIL() << "accepted another command's checkpoint";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("aapat optimize --seed 1"), std::string::npos);
  }
  std::ofstream(path) << "not a checkpoint\n";
  EXPECT_THROW(Checkpoint(path, "aapat optimize --seed 1"), Error);
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "not a checkpoint");  // left as it was
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace aapat
