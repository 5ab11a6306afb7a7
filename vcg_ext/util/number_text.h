// Writing numbers into text files fast: the writers of candidates.obj and field files emit
// millions of coordinates, too many for stream formatting (bench/RESULTS.md).
#pragma once

#include <charconv>
#include <string>

namespace fcql {

/// Appends `x` as printf's "%.<digits>g" would write it (what an ostream with
/// setprecision(digits) writes), through std::to_chars.
inline void appendNumber(std::string& out, double x, int digits) {
  char buffer[40];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, digits);
  out.append(buffer, result.ptr);
}

/// Appends the integer `n`.
inline void appendNumber(std::string& out, long n) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, n);
  out.append(buffer, result.ptr);
}

}  // namespace fcql
