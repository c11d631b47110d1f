// Point sets in the file formats of the field's tools, so that points move
// between aapat and its peers without conversion scripts:
//   csv     aapat's own: "x,y" per line, '#' comments (.csv)
//   safari  Samplin' Safari's CSV export: "x, y" per line, no header; more
//           columns (higher dimensions) are read and the first two kept
//   utk     UTK's text (.dat): "x y" per line, sets separated by a '#' line;
//           also pbrt-v4 pspec's stdin.dat input
//   utk-bin UTK's binary (.bin): per set a uint32 count, then count (x, y)
//           pairs of little-endian doubles, sets one after another
//   psa     PSA's text input (Schloemer & Heck; .txt there): the point count,
//           then "x y" pairs
//   pspec   pbrt-v4 pspec's stdin.binary input (.f32): (x, y) pairs of
//           little-endian 32-bit floats
//   json    an aapat pattern file: its tile's samples scaled onto [0,1)^2
// Every point lies in [0, 1]^2. The format comes from --format (or the
// `format` argument) or else from the file's extension.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

enum class PointFormat { kCsv, kSafari, kUtk, kUtkBinary, kPsa, kPspec, kPattern };

struct PointFormatInfo {
  PointFormat format;
  std::string name;
  std::string extension;  // the one written by default
  std::string summary;
  bool many_sets;  // holds several point sets
};
const std::vector<PointFormatInfo>& point_formats();
const PointFormatInfo& point_format_info(PointFormat format);

// `name` when given, else the extension of `path`; Error naming the choices.
PointFormat point_format(std::string_view path, std::string_view name = "");
// Whether `path` ends in an extension of a point format (a file, not a generator spec).
bool is_point_file(std::string_view path);

using PointSets = std::vector<std::vector<Vec2>>;

// Parses a file's bytes; `source` names it in errors (with the line).
PointSets parse_point_sets(std::string_view bytes, PointFormat format, std::string_view source);
// The bytes of the file; Error when the format holds one set and there are more.
std::string format_point_sets(const PointSets& sets, PointFormat format);

PointSets load_point_sets(const std::string& path, std::string_view format = "");
// Written whole or not at all (io/atomic_file).
void save_point_sets(const PointSets& sets, const std::string& path, std::string_view format = "");

}  // namespace aapat
