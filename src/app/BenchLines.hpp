#pragma once
// The breakdown lines of `oceanglobe bench --breakdown`: per view (BenchCommand) and per band
// of camera height with --record (RecordCommand).
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace og::app {

/// " NAME 12.3 NAME 4.5 ..." (one decimal) for each (name, value) in order, each also set in
/// `json` under its name.
inline std::string namedValuesLine(const std::vector<std::pair<std::string, double>>& values, nlohmann::json& json) {
  std::string line;
  for (const auto& [name, value] : values) {
    json[name] = value;
    char buf[96];
    std::snprintf(buf, sizeof buf, " %s %.1f", name.c_str(), value);
    line += buf;
  }
  return line;
}

}  // namespace og::app
