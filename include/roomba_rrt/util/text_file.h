// Reading a small configuration file: what is not a readable regular file of bounded size is
// refused with a message, before anything is read (a directory, a device, a 50 MB file).
#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::util {

/// The whole text of `path`. Throws InvalidInput "<path>: cannot read the <what> (...)"
/// when it does not exist, is not a regular file or cannot be read, and "<path>: the <what> has
/// N bytes; at most M are supported" when it is larger than `max_bytes`.
inline std::string readTextFile(const std::string& path, std::size_t max_bytes,
                                const std::string& what) {
  const auto fail = [&](const std::string& problem) { throw InvalidInput("", problem, path); };
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status))
    fail("cannot read the " + what + " (no such file)");
  if (!std::filesystem::is_regular_file(status)) {
    fail("cannot read the " + what + " (not a regular file)");
  }
  const auto bytes = std::filesystem::file_size(path, error);
  if (!error && bytes > max_bytes) {
    fail("the " + what + " has " + std::to_string(bytes) + " bytes; at most " +
         std::to_string(max_bytes) + " are supported");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) fail("cannot read the " + what);
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) fail("cannot read the " + what);
  return text;
}

}  // namespace roomba_rrt::util
