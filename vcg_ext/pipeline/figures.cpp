#include "figures.h"

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

Figures::Entry& Figures::entry(const std::string& key) {
  for (Entry& e : entries_)
    if (e.key == key) return e;
  entries_.push_back(Entry{});
  entries_.back().key = key;
  return entries_.back();
}

const Figures::Entry* Figures::find(const std::string& key) const {
  for (const Entry& e : entries_)
    if (e.key == key) return &e;
  return nullptr;
}

void Figures::set(const std::string& key, long long value) {
  Entry& e = entry(key);
  e.kind = Entry::Integer;
  e.integer = value;
}

void Figures::set(const std::string& key, double value) {
  Entry& e = entry(key);
  e.kind = Entry::Real;
  e.real = value;
}

void Figures::set(const std::string& key, bool value) {
  Entry& e = entry(key);
  e.kind = Entry::Flag;
  e.flag = value;
}

void Figures::set(const std::string& key, const std::string& value) {
  Entry& e = entry(key);
  e.kind = Entry::Text;
  e.text = value;
}

void Figures::setCounts(const std::string& key, const std::vector<std::pair<std::string, int>>& counts) {
  if (counts.empty()) entry(key).kind = Entry::EmptyObject;
  for (const auto& c : counts) set(key + "." + c.first, c.second);
}

void Figures::append(const Figures& other) {
  for (const Entry& e : other.entries_) entry(e.key) = e;
}

std::string Figures::literal(const Entry& e) {
  switch (e.kind) {
    case Entry::Integer: return std::to_string(e.integer);
    case Entry::Flag: return e.flag ? "true" : "false";
    case Entry::Text: return jsonQuote(e.text);
    case Entry::EmptyObject: return "{}";
    case Entry::Real: {
      if (!std::isfinite(e.real)) return "null";
      std::ostringstream ss;
      ss.precision(6);
      ss << e.real;
      return ss.str();
    }
  }
  return "null";
}

namespace {

/// The nested form of the dotted keys, in first-insertion order.
struct Node {
  std::string key;
  std::string literal;  ///< a leaf's JSON text; empty for an object
  std::vector<Node> children;
};

Node& child(Node& node, const std::string& key) {
  for (Node& c : node.children)
    if (c.key == key) return c;
  node.children.push_back(Node{key, "", {}});
  return node.children.back();
}

Node& nodeAt(Node& root, const std::string& path) {
  Node* node = &root;
  std::size_t begin = 0;
  while (true) {
    const std::size_t dot = path.find('.', begin);
    node = &child(*node, path.substr(begin, dot == std::string::npos ? std::string::npos : dot - begin));
    if (dot == std::string::npos) return *node;
    node->literal.clear();
    begin = dot + 1;
  }
}

void write(const Node& node, int depth, std::string& out) {
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

}  // namespace

std::string Figures::toJson() const {
  Node root;
  for (const Entry& e : entries_) {
    Node& n = nodeAt(root, e.key);
    n.children.clear();
    n.literal = literal(e);
  }
  std::string out;
  write(root, 0, out);
  return out + "\n";
}

std::string Figures::toFlatJson() const {
  std::string out = "{";
  for (std::size_t i = 0; i < entries_.size(); ++i)
    out += (i ? ", " : "") + jsonQuote(entries_[i].key) + ": " + literal(entries_[i]);
  return out + "}";
}

}  // namespace fcql
