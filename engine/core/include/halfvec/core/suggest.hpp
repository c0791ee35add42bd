// "Did you mean ...?" for names a user typed: the closest candidate by edit distance.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace hv {

// Levenshtein distance (insertions, deletions, substitutions of one byte each).
size_t editDistance(std::string_view a, std::string_view b);

// The candidate closest to `typed` when it is close enough to be a typo (distance at most
// max(2, typed.size() / 3)), else "". Ties go to the first candidate.
std::string closestName(std::string_view typed, std::span<const std::string_view> candidates);

// "; did you mean "NAME"?" for closestName, or "" when there is none.
std::string didYouMeanSuffix(std::string_view typed, std::span<const std::string_view> candidates);

}  // namespace hv
