#include "aapat/io/point_formats.h"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/text.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/point_set_file.h"

namespace aapat {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the binary formats are little-endian; add byte swapping for this machine");

// Collects points, checking the unit square and the size limit.
class SetBuilder {
 public:
  explicit SetBuilder(std::string_view source) : source_(source) {}
  void add(Vec2 p, const std::string& where) {
    if (!(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1))
      throw Error(fmt::format("{}: ({}, {}) lies outside the unit square [0, 1] x [0, 1]", where,
                              p.x, p.y));
    if (++total_ > kMaxPointSetSize)
      throw Error(
          fmt::format("point file {}: more than {} points, the limit", source_, kMaxPointSetSize));
    if (sets_.empty()) sets_.emplace_back();
    sets_.back().push_back(p);
  }
  void next_set() {
    if (!sets_.empty() && !sets_.back().empty()) sets_.emplace_back();
  }
  PointSets finish() {
    if (!sets_.empty() && sets_.back().empty()) sets_.pop_back();
    if (sets_.empty()) throw Error(fmt::format("point file {}: no points", source_));
    return std::move(sets_);
  }

 private:
  std::string source_;
  PointSets sets_;
  size_t total_ = 0;
};

// Whitespace- or comma-separated numbers of one line.
std::vector<double> numbers_of(std::string_view line, char separator, const std::string& where) {
  std::vector<double> v;
  if (separator == ',') {
    const std::string_view t = trim(line);
    if (t.find(',') == std::string_view::npos && t.find_first_of(" \t") != std::string_view::npos)
      throw Error(
          fmt::format("{}: '{}' separates its numbers by spaces; a CSV point file takes "
                      "'x,y' with a comma (or name the format: --format utk for spaces)",
                      where, t));
    for (std::string_view f : split(line)) v.push_back(parse_number(trim(f), where));
    return v;
  }
  std::istringstream in{std::string(line)};
  std::string word;
  while (in >> word) v.push_back(parse_number(word, where));
  return v;
}

// The text formats: one point per line, in columns.
PointSets parse_lines(std::string_view text, PointFormat f, std::string_view source) {
  SetBuilder b(source);
  std::istringstream in{std::string(text)};
  std::string line;
  const char separator = f == PointFormat::kCsv || f == PointFormat::kSafari ? ',' : ' ';
  bool count_pending = f == PointFormat::kPsa;
  size_t expected = 0;
  for (int no = 1; std::getline(in, line); ++no) {
    const std::string where = fmt::format("point file {} line {}", source, no);
    const bool hash = line.find_first_not_of(" \t") != std::string::npos &&
                      line[line.find_first_not_of(" \t")] == '#';
    if (hash && f == PointFormat::kUtk) {
      b.next_set();  // UTK separates sets with '#' lines
      continue;
    }
    if (const auto h = line.find('#'); h != std::string::npos) line.erase(h);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::vector<double> v = numbers_of(line, separator, where);
    if (count_pending) {
      if (v.size() != 1 || v[0] < 0 || v[0] != std::floor(v[0]) || v[0] > kMaxPointSetSize)
        throw Error(fmt::format("{}: expected the point count, got '{}'", where, trim(line)));
      expected = static_cast<size_t>(v[0]);
      count_pending = false;
      continue;
    }
    const bool columns_ok = f == PointFormat::kSafari ? v.size() >= 2 : v.size() == 2;
    if (!columns_ok)
      throw Error(fmt::format("{}: expected '{}', got '{}'", where,
                              f == PointFormat::kCsv      ? "x,y"
                              : f == PointFormat::kSafari ? "x, y"
                                                          : "x y",
                              trim(line)));
    b.add({v[0], v[1]}, where);
  }
  PointSets sets = b.finish();
  if (f == PointFormat::kPsa && sets[0].size() != expected)
    throw Error(fmt::format("point file {}: says {} points but holds {}", source, expected,
                            sets[0].size()));
  return sets;
}

template <class T>
T read_le(std::string_view bytes, size_t at) {
  T v;
  std::memcpy(&v, bytes.data() + at, sizeof(T));
  return v;
}

PointSets parse_utk_binary(std::string_view bytes, std::string_view source) {
  SetBuilder b(source);
  size_t at = 0;
  for (int set = 1; at < bytes.size(); ++set) {
    if (bytes.size() - at < 4)
      throw Error(fmt::format("point file {}: {} stray bytes after set {}", source,
                              bytes.size() - at, set - 1));
    const uint32_t n = read_le<uint32_t>(bytes, at);
    at += 4;
    if (n > (bytes.size() - at) / 16)
      throw Error(fmt::format("point file {}: set {} says {} points but {} bytes follow", source,
                              set, n, bytes.size() - at));
    b.next_set();
    for (uint32_t i = 0; i < n; ++i, at += 16)
      b.add({read_le<double>(bytes, at), read_le<double>(bytes, at + 8)},
            fmt::format("point file {} set {} point {}", source, set, i + 1));
  }
  return b.finish();
}

PointSets parse_pspec(std::string_view bytes, std::string_view source) {
  if (bytes.size() % 8 != 0)
    throw Error(fmt::format("point file {}: {} bytes is not a whole number of (x, y) float pairs",
                            source, bytes.size()));
  SetBuilder b(source);
  for (size_t at = 0; at < bytes.size(); at += 8)
    b.add({read_le<float>(bytes, at), read_le<float>(bytes, at + 4)},
          fmt::format("point file {} point {}", source, at / 8 + 1));
  return b.finish();
}

template <class T>
void append_le(std::string& out, T v) {
  char buf[sizeof(T)];
  std::memcpy(buf, &v, sizeof(T));
  out.append(buf, sizeof(T));
}

}  // namespace

const std::vector<PointFormatInfo>& point_formats() {
  static const std::vector<PointFormatInfo> kFormats = {
      {PointFormat::kCsv, "csv", ".csv", "aapat: 'x,y' per line, '#' comments", false},
      {PointFormat::kSafari, "safari", ".csv", "Samplin' Safari's CSV export: 'x, y' per line",
       false},
      {PointFormat::kUtk, "utk", ".dat", "UTK text: 'x y' per line, sets separated by '#'", true},
      {PointFormat::kUtkBinary, "utk-bin", ".bin",
       "UTK binary: per set a uint32 count and (x, y) doubles", true},
      {PointFormat::kPsa, "psa", ".psa", "PSA text: the point count, then 'x y' pairs", false},
      {PointFormat::kPspec, "pspec", ".f32", "pbrt-v4 pspec stdin.binary: (x, y) float32 pairs",
       false},
      {PointFormat::kPattern, "json", ".json", "an aapat pattern file, its tile on [0,1)^2", false},
  };
  return kFormats;
}

const PointFormatInfo& point_format_info(PointFormat format) {
  for (const auto& f : point_formats())
    if (f.format == format) return f;
  throw Error("point format: unknown");
}

PointFormat point_format(std::string_view path, std::string_view name) {
  std::string names;
  for (const auto& f : point_formats()) {
    if (!name.empty() && f.name == name) return f.format;
    names += (names.empty() ? "" : ", ") + f.name;
  }
  if (!name.empty())
    throw ParameterError("format", fmt::format(" '{}': point formats are {}", name, names));
  // By extension: the first format that writes it (.csv: aapat's own, which
  // reads Safari's two-column files too).
  for (const auto& f : point_formats())
    if (path.ends_with(f.extension)) return f.format;
  throw ParameterError(
      "format", fmt::format(": '{}' has no extension of a point format (.csv, .dat, .bin, .psa, "
                            ".f32, .json); name one: {}",
                            path, names));
}

bool is_point_file(std::string_view path) {
  for (const auto& f : point_formats())
    if (path.ends_with(f.extension)) return true;
  return path.ends_with(".txt");
}

PointSets parse_point_sets(std::string_view bytes, PointFormat format, std::string_view source) {
  switch (format) {
    case PointFormat::kUtkBinary:
      return parse_utk_binary(bytes, source);
    case PointFormat::kPspec:
      return parse_pspec(bytes, source);
    case PointFormat::kPattern:
      return {pattern_points(pattern_from_json(bytes, source))};
    default:
      return parse_lines(bytes, format, source);
  }
}

std::string format_point_sets(const PointSets& sets, PointFormat format) {
  const PointFormatInfo& info = point_format_info(format);
  if (sets.empty()) throw Error(fmt::format("{} file: no point set to write", info.name));
  if (sets.size() > 1 && !info.many_sets)
    throw Error(fmt::format("{} files hold one point set, not {}: write utk or utk-bin", info.name,
                            sets.size()));
  std::string out;
  switch (format) {
    case PointFormat::kCsv:
      return point_csv(sets[0]);
    case PointFormat::kSafari:
      for (const Vec2& p : sets[0]) out += fmt::format("{}, {}\n", p.x, p.y);
      return out;
    case PointFormat::kUtk:
      for (size_t s = 0; s < sets.size(); ++s) {
        if (s > 0) out += "#\n";
        for (const Vec2& p : sets[s]) out += fmt::format("{} {}\n", p.x, p.y);
      }
      return out;
    case PointFormat::kUtkBinary:
      for (const auto& set : sets) {
        append_le(out, static_cast<uint32_t>(set.size()));
        for (const Vec2& p : set) append_le(out, p.x), append_le(out, p.y);
      }
      return out;
    case PointFormat::kPsa:
      out = fmt::format("{}\n", sets[0].size());
      for (const Vec2& p : sets[0]) out += fmt::format("{} {}\n", p.x, p.y);
      return out;
    case PointFormat::kPspec:
      for (const Vec2& p : sets[0])
        append_le(out, static_cast<float>(p.x)), append_le(out, static_cast<float>(p.y));
      return out;
    case PointFormat::kPattern:
      break;
  }
  throw Error("json: write a pattern with the pattern commands, not a point set");
}

PointSets load_point_sets(const std::string& path, std::string_view format) {
  return parse_point_sets(read_file(path, "point file"), point_format(path, format), path);
}

void save_point_sets(const PointSets& sets, const std::string& path, std::string_view format) {
  write_file_atomically(path, format_point_sets(sets, point_format(path, format)));
}

}  // namespace aapat
