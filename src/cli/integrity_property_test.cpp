// A damaged cache entry or checkpoint never changes an answer (issue 26):
// each is damaged at random (bits flipped; cut short; grown; bytes
// overwritten, deleted or repeated; a checkpoint's records renumbered,
// swapped, dropped or repeated; a cached value replaced by 1 - v or NaN), and
// input files are edited between runs, a texture named inside a scene file
// among them. Every run then prints the same bytes as a clean run (the damage
// is found and the work done again) or refuses with a message naming the
// checkpoint. The cases are drawn from a fixed seed, so a failure names a
// case that can be run again.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "aapat/io/png_image.h"
#include "testing/cli_run.h"

namespace aapat {
namespace {

namespace fs = std::filesystem;
using testing::run;
using testing::slurp;
using testing::temp_path;

#if defined(__SANITIZE_ADDRESS__)
constexpr int kCases = 40;  // each run is about five times slower under ASan
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int kCases = 40;
#else
constexpr int kCases = 200;
#endif
#else
constexpr int kCases = 200;
#endif

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// One of the ways a file can be damaged, applied to `bytes`; `what` says which.
std::string damage(std::string bytes, std::mt19937_64& rng, std::string& what) {
  auto pick = [&](size_t n) { return n == 0 ? size_t{0} : static_cast<size_t>(rng() % n); };
  const size_t n = bytes.size();
  switch (rng() % 6) {
    case 0: {
      const int flips = 1 + static_cast<int>(rng() % 8);
      for (int i = 0; i < flips; ++i) bytes[pick(n)] ^= static_cast<char>(1u << (rng() % 8));
      what = fmt::format("{} bits flipped", flips);
      break;
    }
    case 1:
      bytes.resize(pick(n));
      what = fmt::format("cut to {} of {} bytes", bytes.size(), n);
      break;
    case 2: {
      const size_t extra = 1 + pick(64);
      for (size_t i = 0; i < extra; ++i) bytes += static_cast<char>(rng());
      what = fmt::format("{} random bytes appended", extra);
      break;
    }
    case 3: {
      const size_t at = pick(n), len = std::min(n - at, 1 + pick(32));
      for (size_t i = 0; i < len; ++i) bytes[at + i] = static_cast<char>(rng());
      what = fmt::format("{} bytes at {} overwritten", len, at);
      break;
    }
    case 4: {
      const size_t at = pick(n), len = std::min(n - at, 1 + pick(64));
      bytes.erase(at, len);
      what = fmt::format("{} bytes at {} deleted", len, at);
      break;
    }
    default: {
      const size_t at = pick(n), len = std::min(n - at, 1 + pick(64));
      bytes.insert(at, bytes.substr(at, len));
      what = fmt::format("{} bytes at {} repeated", len, at);
      break;
    }
  }
  return bytes;
}

// A checkpoint's records: the header lines, then "item CALL ITEM SIZE SUM\n"
// + bytes + "\n" each.
struct Record {
  size_t begin, end;  // the whole record, head to its closing newline
  size_t index_at, index_len;
};
std::vector<Record> records_of(const std::string& data) {
  std::vector<Record> out;
  size_t at = 0;
  while ((at = data.find("\nitem ", at)) != std::string::npos) {
    const size_t head = at + 1, eol = data.find('\n', head);
    std::istringstream in(data.substr(head, eol - head));
    std::string word;
    int call = 0, item = 0;
    size_t size = 0;
    in >> word >> call >> item >> size;
    const size_t second = data.find(' ', data.find(' ', head) + 1) + 1;
    out.push_back({head, eol + 1 + size + 1, second, data.find(' ', second) - second});
    at = eol + 1 + size;
  }
  return out;
}

std::string damage_records(std::string data, std::mt19937_64& rng, std::string& what) {
  std::vector<Record> r = records_of(data);
  if (r.size() < 2) return damage(data, rng, what);
  const size_t a = rng() % r.size(), b = (a + 1 + rng() % (r.size() - 1)) % r.size();
  switch (rng() % 4) {
    case 0:  // renumbered
      data.replace(r[a].index_at, r[a].index_len,
                   std::to_string((std::stoi(data.substr(r[a].index_at, r[a].index_len)) + 1 +
                                   static_cast<int>(rng() % 7)) %
                                  8));
      what = fmt::format("record {} renumbered", a);
      break;
    case 1: {  // two records' bytes exchanged, their heads kept
      const std::string ra = data.substr(r[a].begin, r[a].end - r[a].begin),
                        rb = data.substr(r[b].begin, r[b].end - r[b].begin);
      const size_t ha = ra.find('\n') + 1, hb = rb.find('\n') + 1;
      const std::string na = ra.substr(0, ha) + rb.substr(hb),
                        nb = rb.substr(0, hb) + ra.substr(ha);
      const size_t lo = std::min(a, b), hi = std::max(a, b);
      const std::string& first = lo == a ? na : nb;
      const std::string& second = lo == a ? nb : na;
      data = data.substr(0, r[lo].begin) + first + data.substr(r[lo].end, r[hi].begin - r[lo].end) +
             second + data.substr(r[hi].end);
      what = fmt::format("records {} and {} exchanged their bytes", a, b);
      break;
    }
    case 2:  // dropped
      data.erase(r[a].begin, r[a].end - r[a].begin);
      what = fmt::format("record {} dropped", a);
      break;
    default:  // repeated at the end
      data += data.substr(r[a].begin, r[a].end - r[a].begin);
      what = fmt::format("record {} repeated", a);
      break;
  }
  return data;
}

const std::vector<std::string> kRender = {"render", "zoneplate", "--pattern", "msaa-4",
                                          "--size", "24x24",     "--json",    "--reference-samples",
                                          "16"};

std::vector<std::string> with(std::vector<std::string> base, const std::vector<std::string>& more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

TEST(Integrity, DamagedCacheEntriesAreRenderedAgain) {
  const std::string dir = temp_path("cache");
  fs::remove_all(dir);
  const auto clean = run(with(kRender, {"--no-cache"}));
  ASSERT_EQ(clean.code, 0) << clean.err;
  const auto cached = with(kRender, {"--cache", dir});
  ASSERT_EQ(run(cached).out, clean.out);
  ASSERT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
  const std::string entry = fs::directory_iterator(dir)->path().string(), pristine = slurp(entry);
  std::mt19937_64 rng(2026);
  int refound = 0;
  for (int c = 0; c < kCases; ++c) {
    std::string what, bytes;
    if (rng() % 3 == 0) {
      // A stored value (the entry ends with them, 8 bytes each) replaced by 1 - v or NaN.
      bytes = pristine;
      const size_t values = 24 * 24, k = rng() % values;
      const size_t at = bytes.size() - 8 * (values - k);
      double v = 0;
      std::memcpy(&v, bytes.data() + at, 8);
      v = rng() % 2 ? 1 - v : std::numeric_limits<double>::quiet_NaN();
      std::memcpy(bytes.data() + at, &v, 8);
      what = fmt::format("value {} replaced by {}", k, v);
    } else {
      bytes = damage(pristine, rng, what);
    }
    write_bytes(entry, bytes);
    const auto r = run(cached);
    ASSERT_EQ(r.code, 0) << "case " << c << " (" << what << "): " << r.err;
    ASSERT_EQ(r.out, clean.out) << "case " << c << " (" << what << ") changed the answer";
    refound += bytes != pristine && r.err.find("rendering it afresh") != std::string::npos;
    ASSERT_EQ(slurp(entry), pristine) << "case " << c << " (" << what << "): entry not restored";
  }
  EXPECT_GT(refound, kCases / 2);  // most damage is seen and said, not just survived
}

TEST(Integrity, DamagedCheckpointsResumeToTheSameBytesOrAreRefused) {
  const std::string ck = temp_path("run.ckpt");
  fs::remove(ck);
  // 72 rows: three reference bands of 32 rows, three records to damage.
  const std::vector<std::string> render = {
      "render", "zoneplate", "--pattern",           "msaa-4", "--size",
      "24x72",  "--json",    "--reference-samples", "16",     "--no-cache"};
  const auto command = with({"--checkpoint", ck}, render);
  const auto clean = run(render);
  ASSERT_EQ(clean.code, 0) << clean.err;
  ASSERT_EQ(run(command).out, clean.out);
  const std::string pristine = slurp(ck);
  ASSERT_EQ(records_of(pristine).size(), 3u);
  std::mt19937_64 rng(26);
  int refused = 0;
  for (int c = 0; c < kCases; ++c) {
    std::string what;
    const std::string bytes =
        rng() % 2 ? damage_records(pristine, rng, what) : damage(pristine, rng, what);
    write_bytes(ck, bytes);
    const auto r = run(command);
    if (r.code != 0) {
      ++refused;
      ASSERT_NE(r.err.find("--checkpoint " + ck), std::string::npos)
          << "case " << c << " (" << what << "): " << r.err;
    } else {
      ASSERT_EQ(r.out, clean.out) << "case " << c << " (" << what << ") changed the answer";
    }
  }
  EXPECT_LT(refused, kCases);  // most damage is recomputed, not refused
}

// A checkpoint is bound to every input the run read: a scene file named on
// the command line, and the texture the scene file names.
TEST(Integrity, ACheckpointDoesNotResumeAfterAnInputChanged) {
  const std::string scene = temp_path("scene.json"), texture = temp_path("wood.png"),
                    ck = temp_path("scene.ckpt");
  fs::remove(ck);
  auto write_texture = [&](uint8_t level) {
    std::vector<uint8_t> px(8 * 8);
    for (size_t i = 0; i < px.size(); ++i) px[i] = i % 3 ? level : 255;
    write_png_gray(texture, 8, 8, px);
  };
  auto write_scene = [&](double grey) {
    write_bytes(scene, fmt::format(R"({{"background": 0, "shapes": [
      {{"polygon": [[2, 2], [22, 3], [21, 22], [3, 20]], "uv": [[0, 0], [1, 0], [1, 1], [0, 1]],
        "texture": "{}", "grey": {}}}]}})",
                                   texture, grey));
  };
  write_texture(40);
  write_scene(0.8);
  const std::vector<std::string> render = {"render", scene,       "--pattern",           "msaa-4",
                                           "--size", "24x24",     "--reference-samples", "16",
                                           "--json", "--no-cache"};
  const auto command = with({"--checkpoint", ck}, render);
  const auto first = run(command);
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_EQ(run(command).out, first.out);  // resumed, nothing changed

  write_texture(200);  // the texture, named only inside the scene file
  auto r = run(command);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--checkpoint " + ck +
                       ": the files the run read have changed since it "
                       "was written ('" +
                       texture + "' changed)"),
            std::string::npos)
      << r.err;
  fs::remove(ck);
  const auto fresh = run(command);
  ASSERT_EQ(fresh.code, 0) << fresh.err;
  EXPECT_NE(fresh.out, first.out);

  write_scene(0.3);  // the scene file itself
  r = run(command);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--checkpoint " + ck + ": it belongs to another command"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace aapat
