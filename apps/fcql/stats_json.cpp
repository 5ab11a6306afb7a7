#include "stats_json.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace fcql {

std::string jsonQuote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

StatsJson::Node& StatsJson::nodeAt(const std::string& path) {
  Node* node = &root_;
  std::size_t begin = 0;
  while (true) {
    std::size_t dot = path.find('.', begin);
    std::string key = path.substr(begin, dot == std::string::npos ? std::string::npos : dot - begin);
    Node* child = nullptr;
    for (auto& c : node->children)
      if (c.key == key) child = &c;
    if (!child) {
      node->children.push_back(Node{key, "", {}});
      child = &node->children.back();
    }
    node = child;
    if (dot == std::string::npos) return *node;
    node->literal.clear();
    begin = dot + 1;
  }
}

void StatsJson::setLiteral(const std::string& path, std::string literal) {
  Node& n = nodeAt(path);
  n.children.clear();
  n.literal = std::move(literal);
}

void StatsJson::set(const std::string& path, long long value) { setLiteral(path, std::to_string(value)); }
void StatsJson::set(const std::string& path, bool value) { setLiteral(path, value ? "true" : "false"); }
void StatsJson::set(const std::string& path, const std::string& value) { setLiteral(path, jsonQuote(value)); }
void StatsJson::set(const std::string& path, double value) {
  if (!std::isfinite(value)) return setLiteral(path, "null");
  std::ostringstream ss;
  ss.precision(6);
  ss << value;
  setLiteral(path, ss.str());
}

void StatsJson::setCounts(const std::string& path, const std::vector<std::pair<std::string, int>>& counts) {
  Node& n = nodeAt(path);
  n.literal.clear();
  n.children.clear();
  for (const auto& c : counts) n.children.push_back(Node{c.first, std::to_string(c.second), {}});
  if (counts.empty()) n.literal = "{}";
}

void StatsJson::write(const Node& node, int depth, std::string& out) {
  if (!node.literal.empty()) {
    out += node.literal;
    return;
  }
  out += "{";
  for (std::size_t i = 0; i < node.children.size(); ++i) {
    out += i ? ",\n" : "\n";
    out += std::string(2 * (depth + 1), ' ') + jsonQuote(node.children[i].key) + ": ";
    write(node.children[i], depth + 1, out);
  }
  out += node.children.empty() ? "}" : "\n" + std::string(2 * depth, ' ') + "}";
}

std::string StatsJson::toString() const {
  std::string out;
  write(root_, 0, out);
  return out + "\n";
}

}  // namespace fcql
