// A file's pattern or sequence never passes for a catalog entry it is not.
// A file may hold a catalog name (`aapat show rgss -o rgss.json` writes one,
// and an optimization run from a catalog script names its result so), but
// when its samples differ from the entry's, the name would make two rows of
// one comparison look like the same entry with different numbers: it is read
// under the file's own name instead, with a warning.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "aapat/core/pattern.h"

namespace aapat {

// Tile, footprint, every sample and every weight equal.
bool same_samples(const Pattern& a, const Pattern& b);

// The name to read `name` under from the file at `path` when a catalog entry
// of that name differs from the file's content: the file's stem, or
// NAME-edited when the stem is taken too (`taken` says which names are
// catalog entries). Warns (core/warning.h), naming `what` and the file.
std::string name_off_the_catalog(std::string_view name, const std::string& path,
                                 const std::function<bool(std::string_view)>& taken,
                                 std::string_view what);

}  // namespace aapat
