// A small JSON value for writing summary.json and reading it back (polydem
// sweep reads each point's summary.json); no external library.
//
// Objects keep their keys in insertion order, so the summary reads the way it
// was built. Numbers: integers are printed exactly; doubles with the shortest
// text that reads back to the same bits (std::to_chars, at most 17 significant
// digits, i.e. full round-trip precision), or to a fixed number of
// significant digits when dump() is asked for one (printf's %.Ng, as
// `polydem analytic --json` prints its results). JSON has no NaN or infinity: they
// are written as null. Strings are UTF-8; '"', '\\' and control characters
// are escaped.
//
//   Json s = Json::object();
//   s["status"] = "intact";
//   Json& checks = s["checks"] = Json::array();
//   checks.push_back(Json::object().set("name", "period").set("measured", 0.51)
//                        .set("expected", 0.5).set("tolerance", 0.02).set("passed", true));
//   write_file_atomic("summary.json", s.dump() + "\n");
#pragma once

#include <concepts>
#include <cstdint>
#include <cstddef>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

namespace polydem {

class Json {
 public:
  enum class Type { Null, Bool, Integer, Number, String, Array, Object };

  Json() = default;  // null
  Json(std::nullptr_t) {}
  Json(bool b) : type_(Type::Bool), bool_(b) {}
  Json(double x) : type_(Type::Number), number_(x) {}
  template <std::integral T>
    requires(!std::same_as<T, bool>)
  Json(T i) : type_(Type::Integer), integer_(static_cast<std::int64_t>(i)) {}
  Json(const char* s) : type_(Type::String), string_(s) {}
  Json(std::string s) : type_(Type::String), string_(std::move(s)) {}
  Json(const std::vector<double>& xs);        // array of numbers
  Json(const std::vector<std::string>& xs);   // array of strings

  static Json object();
  static Json array();

  Type type() const { return type_; }
  bool is_null() const { return type_ == Type::Null; }
  std::size_t size() const;  // elements of an array / keys of an object, else 0

  // Object access: inserts null under a new key (a null value becomes an
  // empty object first). Throws std::logic_error on other types. Like
  // std::vector, references into a container are invalidated by later
  // insertions into that same container.
  Json& operator[](const std::string& key);
  // Sets key (replacing an existing value in place, keeping its position).
  Json& set(const std::string& key, Json value) &;
  Json&& set(const std::string& key, Json value) &&;
  // Object lookup without insertion; nullptr when absent or not an object.
  const Json* find(const std::string& key) const;
  const std::vector<std::string>& keys() const { return keys_; }

  // Array append (a null value becomes an empty array first).
  Json& push_back(Json value) &;
  Json&& push_back(Json value) &&;
  // Array element or object value by position.
  const Json& at(std::size_t i) const;

  // Scalar accessors (throw std::logic_error on the wrong type; as_number
  // accepts integers too).
  bool as_bool() const;
  double as_number() const;
  std::int64_t as_integer() const;
  const std::string& as_string() const;

  // Parses JSON text (RFC 8259; numbers without '.', 'e' or 'E' that fit
  // in 64 bits become integers). Throws std::runtime_error naming `what`
  // (e.g. the file) and the byte offset of the first error. Nesting deeper
  // than 256 levels is rejected rather than risking the stack.
  static Json parse(std::string_view text, const std::string& what = "JSON text");

  // Text. indent > 0: pretty-printed with that many spaces per level;
  // indent <= 0: compact on one line. significant_digits > 0: every double
  // to that many significant digits (printf's %.Ng); 0: the shortest round
  // trip.
  std::string dump(int indent = 2, int significant_digits = 0) const;

 private:
  void dump_to(std::string& out, int indent, int level, int digits) const;

  Type type_ = Type::Null;
  bool bool_ = false;
  std::int64_t integer_ = 0;
  double number_ = 0;
  std::string string_;
  std::vector<std::string> keys_;  // Object: keys, parallel to items_
  std::vector<Json> items_;        // Array elements or Object values
};

// JSON text for a double: shortest round-trip form (significant_digits 0)
// or printf's %.Ng with N = significant_digits; "null" for NaN/inf.
std::string json_number(double x, int significant_digits = 0);
// JSON string literal with quotes and escapes.
std::string json_quote(const std::string& s);

}  // namespace polydem
