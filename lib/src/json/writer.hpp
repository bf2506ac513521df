#pragma once
// What every JSON writer of lib/src/json shares.

#include <string>

#include <nlohmann/json.hpp>

namespace pendulum {

/// JSON text as every command prints it (indent -1: one line). Throws
/// std::logic_error at a number that is not finite, which the JSON library
/// would print as null where the API promises a number. A file name that is
/// not UTF-8 prints its bad bytes as U+FFFD instead of failing.
std::string json_text(const nlohmann::ordered_json& j, int indent);

}  // namespace pendulum
