// References cached on disk by their parameters: a dense reference takes
// seconds to minutes, and the same one is asked for again and again while a
// user compares patterns. The file name is a hash of the scene's exact text
// (canonical_text), the size, offset and reference settings; the file repeats
// that text, which is compared on load, so a hash collision reads as a miss.
#pragma once

#include <string>

#include "aapat/render/reference.h"

namespace aapat {

// The default folder: $AAPAT_CACHE, else $XDG_CACHE_HOME/aapat, else ~/.cache/aapat.
std::string default_cache_dir();

// A reference source that reads from and writes to `dir` (created when
// needed), rendering with `render` what it does not hold. A folder that
// cannot be made or written is not an error: `warn` hears why once, and the
// references are rendered without the cache.
using Warn = std::function<void(const std::string&)>;
ReferenceSource cached_references(std::string dir, Warn warn = {},
                                  ReferenceSource render = render_reference);

// `source` with the references of this run kept in memory (up to 1 GiB), so
// that patterns compared on the same scenes share each reference.
ReferenceSource remembered_references(ReferenceSource source);

}  // namespace aapat
