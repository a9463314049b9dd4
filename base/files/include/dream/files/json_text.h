#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace dream::files {

/// `json` as text, indented by `indent` spaces (-1: one line). Bytes that are
/// not UTF-8 (a folder's name or a path given on the command line) become
/// U+FFFD instead of making the JSON library throw, so a summary, report or
/// log line is never lost to a name. Every JSON file and line dream writes
/// goes through here.
template <typename Json>
std::string JsonText(const Json& json, int indent = 2) {
  return json.dump(indent, ' ', false, Json::error_handler_t::replace);
}

}  // namespace dream::files
