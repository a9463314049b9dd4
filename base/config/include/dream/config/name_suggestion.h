#pragma once

#include <string>
#include <vector>

namespace dream::config {

/// " (did you mean 'tolerance_m'?)" when `given` looks like a typo of one of
/// `names`: the same but for case, one or two letters wrong, missing, extra or
/// swapped (fewer for short names), or the start of one ("spacing" for
/// "spacing_m"); "" when nothing is that close. The closest name wins, the
/// first listed among equals. For the errors that name an unknown key, kind
/// or choice, so a researcher's typo is answered with the fix.
std::string DidYouMean(const std::string& given, const std::vector<std::string>& names);

}  // namespace dream::config
