// "Did you mean ...?" for a mistyped name: the known name nearest to it by
// edit distance, offered only when it is near enough to be a typo.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace aapat {

// Edits from a to b (insertions, deletions, substitutions and swaps of two
// neighbours: the optimal string alignment distance), case-insensitive.
size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest to `name`, if it is within a third of the longer
// name's length (at least 1, at most 3 edits) or `name` is a prefix of it.
std::optional<std::string> nearest_name(std::string_view name,
                                        const std::vector<std::string>& candidates);

// " (did you mean 'X'?)" or "".
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace aapat
