// StatsJson: the nested, ordered key/value record written as stats.json.
// Keys are dotted paths ("mesh.faces"); insertion order is kept so the file reads top-down.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fcql {

class StatsJson {
public:
  void set(const std::string& path, long long value);
  void set(const std::string& path, int value) { set(path, static_cast<long long>(value)); }
  void set(const std::string& path, long value) { set(path, static_cast<long long>(value)); }
  void set(const std::string& path, double value);
  void set(const std::string& path, const std::string& value);
  void set(const std::string& path, bool value);
  /// Writes an object of integer counts, e.g. {"-1/4": 16, "1/4": 8}.
  void setCounts(const std::string& path, const std::vector<std::pair<std::string, int>>& counts);
  std::string toString() const;

private:
  struct Node {
    std::string key;
    std::string literal;  ///< the JSON text of a leaf; empty for an object
    std::vector<Node> children;
  };
  Node& nodeAt(const std::string& path);
  void setLiteral(const std::string& path, std::string literal);
  static void write(const Node& node, int depth, std::string& out);
  Node root_;
};

std::string jsonQuote(const std::string& s);

}  // namespace fcql
