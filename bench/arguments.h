// How the benchmark executables read their command line, in one place: flags read one by one, a
// mistake named with the usage on stderr (exit 2), --help or -h printing the usage on stdout
// (exit 0), counts read whole.
//
//   bench::Arguments args(argc, argv, "map_comparison", kUsage);
//   while (args.next()) {
//     if (args.is("--json")) cfg.json = true;
//     else if (args.is("--runs")) cfg.runs = args.count(1);
//     else args.unknown();
//   }
#pragma once

#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

namespace roomba_rrt::bench {

/// Exits with `usage` ("usage: tool [--flag N] ..."): after "<tool>: <error>" on stderr with
/// code 2, or, when `error` is empty (--help), alone on stdout with code 0.
[[noreturn]] inline void exitWithUsage(const std::string& tool, const std::string& error,
                                       const std::string& usage) {
  if (error.empty()) {
    std::cout << usage;
    std::exit(0);
  }
  std::cerr << tool << ": " << error << "\n" << usage;
  std::exit(2);
}

/// A count on the command line: a whole number from 0 to `max` and nothing else, or nothing.
inline std::optional<long> countFrom(const std::string& text, long max = 1000000000) {
  try {
    std::size_t used = 0;
    const long v = std::stol(text, &used);
    if (used == text.size() && v >= 0 && v <= max) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

/// A benchmark's command line, read flag by flag (see the example above).
class Arguments {
 public:
  Arguments(int argc, char** argv, std::string tool, std::string usage)
      : argc_(argc), argv_(argv), tool_(std::move(tool)), usage_(std::move(usage)) {}

  /// Moves to the next flag; false after the last. --help or -h: the usage, exit 0.
  bool next() {
    if (++i_ >= argc_) return false;
    flag_ = argv_[i_];
    if (flag_ == "--help" || flag_ == "-h") exitWithUsage(tool_, "", usage_);
    return true;
  }
  bool is(const char* flag) const { return flag_ == flag; }
  const std::string& flag() const { return flag_; }

  /// The current flag's value (the next argument); none: the usage, exit 2.
  std::string value() {
    if (i_ + 1 >= argc_) fail(flag_ + ": missing value");
    return argv_[++i_];
  }
  /// The current flag's value as a count from `min` to 10^9.
  int count(int min = 0) { return countOf(value(), min); }
  /// `text` (a value of the current flag) as a count from `min` to 10^9.
  int countOf(const std::string& text, int min = 0) const {
    const std::optional<long> v = countFrom(text);
    if (!v || *v < min) {
      fail(flag_ + ": expected an integer from " + std::to_string(min) + " to 10^9, got '" + text +
           "'");
    }
    return static_cast<int>(*v);
  }

  [[noreturn]] void fail(const std::string& error) const { exitWithUsage(tool_, error, usage_); }
  [[noreturn]] void unknown() const { fail("unknown argument '" + flag_ + "'"); }

 private:
  int argc_;
  char** argv_;
  std::string tool_;
  std::string usage_;
  int i_ = 0;
  std::string flag_;
};

}  // namespace roomba_rrt::bench
