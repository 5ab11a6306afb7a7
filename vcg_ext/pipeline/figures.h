// Figures: the record of what a pipeline stage measured, under stable dotted names
// ("layout.t_junctions", "time_s.tracing"). One record feeds every front end: stats.json
// (nested by the dots), the MeshLab log (one line of flat JSON) and the dictionary pymeshlab
// returns (flat keys). Insertion order is kept; setting a key again replaces its value in place.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace fcql {

class Figures {
public:
  struct Entry {
    enum Kind { Integer, Real, Flag, Text, EmptyObject };  ///< EmptyObject: an empty count list
    std::string key;
    Kind kind = Integer;
    long long integer = 0;
    double real = 0;
    bool flag = false;
    std::string text;
  };

  void set(const std::string& key, long long value);
  void set(const std::string& key, int value) { set(key, static_cast<long long>(value)); }
  void set(const std::string& key, long value) { set(key, static_cast<long long>(value)); }
  void set(const std::string& key, std::size_t value) { set(key, static_cast<long long>(value)); }
  void set(const std::string& key, double value);
  void set(const std::string& key, bool value);
  void set(const std::string& key, const std::string& value);
  void set(const std::string& key, const char* value) { set(key, std::string(value)); }
  /// Integer counts under `key`: key.NAME for each (e.g. field.by_index.-1/4). An empty list
  /// leaves `key` as an empty object in stats.json.
  void setCounts(const std::string& key, const std::vector<std::pair<std::string, int>>& counts);
  /// Appends (or replaces) every entry of `other`, in its order.
  void append(const Figures& other);

  const std::vector<Entry>& entries() const { return entries_; }
  const Entry* find(const std::string& key) const;

  /// stats.json: nested objects split at the dots, two-space indent, reals with 6 significant
  /// digits (non-finite ones as null), a final newline.
  std::string toJson() const;
  /// One line of flat JSON, {"mesh.faces": 1234, ...}, reals as in toJson.
  std::string toFlatJson() const;
  /// A value as toJson writes it.
  static std::string literal(const Entry& e);

private:
  Entry& entry(const std::string& key);
  std::vector<Entry> entries_;
};

std::string jsonQuote(const std::string& s);

}  // namespace fcql
