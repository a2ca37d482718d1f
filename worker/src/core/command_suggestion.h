// "Did you mean": the nearest of a command's known names to a mistyped one.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gridfree {

// Edit distance counting insertions, deletions, substitutions and swaps of
// two neighbouring characters as one edit each.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The name in `names` nearest to `word` if at most 2 edits away (and fewer
// than the name's length), else "".
std::string nearest_name(std::string_view word, const std::vector<std::string>& names);

// "unknown command 'stauts'; did you mean 'status'?" or, with no near name,
// "unknown command 'x'; commands: a, b, c".
std::string unknown_command_message(std::string_view word, const std::vector<std::string>& names);

}  // namespace gridfree
