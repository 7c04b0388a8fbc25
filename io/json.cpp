#include "io/json.hpp"

#include "core/number_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace polydem {
namespace {

const char* type_name(Json::Type t) {
  switch (t) {
    case Json::Type::Null: return "null";
    case Json::Type::Bool: return "bool";
    case Json::Type::Integer: return "integer";
    case Json::Type::Number: return "number";
    case Json::Type::String: return "string";
    case Json::Type::Array: return "array";
    case Json::Type::Object: return "object";
  }
  return "?";
}

[[noreturn]] void wrong_type(const char* wanted, Json::Type got) {
  throw std::logic_error(std::string("Json: expected ") + wanted + ", value is " + type_name(got));
}

void newline(std::string& out, int indent, int level) {
  if (indent <= 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent) * static_cast<std::size_t>(level), ' ');
}

}  // namespace

std::string json_number(double x, int significant_digits) {
  if (!std::isfinite(x)) return "null";
  if (significant_digits <= 0) return shortest_text(x);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, x);
  return buf;
}

std::string json_quote(const std::string& s) {
  std::string out;
  out.reserve(s.size() + 2);
  out += '"';
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          static const char hex[] = "0123456789abcdef";
          out += "\\u00";
          out += hex[c >> 4];
          out += hex[c & 0xF];
        } else {
          out += ch;  // UTF-8 bytes pass through
        }
    }
  }
  out += '"';
  return out;
}

Json::Json(const std::vector<double>& xs) : type_(Type::Array) {
  items_.reserve(xs.size());
  for (double x : xs) items_.emplace_back(x);
}

Json::Json(const std::vector<std::string>& xs) : type_(Type::Array) {
  items_.reserve(xs.size());
  for (const std::string& x : xs) items_.emplace_back(x);
}

Json Json::object() {
  Json j;
  j.type_ = Type::Object;
  return j;
}

Json Json::array() {
  Json j;
  j.type_ = Type::Array;
  return j;
}

std::size_t Json::size() const {
  return (type_ == Type::Array || type_ == Type::Object) ? items_.size() : 0;
}

Json& Json::operator[](const std::string& key) {
  if (type_ == Type::Null) type_ = Type::Object;
  if (type_ != Type::Object) wrong_type("object", type_);
  for (std::size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i] == key) return items_[i];
  keys_.push_back(key);
  items_.emplace_back();
  return items_.back();
}

Json& Json::set(const std::string& key, Json value) & {
  (*this)[key] = std::move(value);
  return *this;
}

Json&& Json::set(const std::string& key, Json value) && {
  (*this)[key] = std::move(value);
  return std::move(*this);
}

const Json* Json::find(const std::string& key) const {
  if (type_ != Type::Object) return nullptr;
  for (std::size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i] == key) return &items_[i];
  return nullptr;
}

Json& Json::push_back(Json value) & {
  if (type_ == Type::Null) type_ = Type::Array;
  if (type_ != Type::Array) wrong_type("array", type_);
  items_.push_back(std::move(value));
  return *this;
}

Json&& Json::push_back(Json value) && {
  push_back(std::move(value));
  return std::move(*this);
}

const Json& Json::at(std::size_t i) const {
  if (type_ != Type::Array && type_ != Type::Object) wrong_type("array or object", type_);
  if (i >= items_.size()) throw std::out_of_range("Json::at: index out of range");
  return items_[i];
}

bool Json::as_bool() const {
  if (type_ != Type::Bool) wrong_type("bool", type_);
  return bool_;
}

double Json::as_number() const {
  if (type_ == Type::Integer) return static_cast<double>(integer_);
  if (type_ != Type::Number) wrong_type("number", type_);
  return number_;
}

std::int64_t Json::as_integer() const {
  if (type_ != Type::Integer) wrong_type("integer", type_);
  return integer_;
}

const std::string& Json::as_string() const {
  if (type_ != Type::String) wrong_type("string", type_);
  return string_;
}

std::string Json::dump(int indent, int significant_digits) const {
  std::string out;
  dump_to(out, indent, 0, significant_digits);
  return out;
}

void Json::dump_to(std::string& out, int indent, int level, int digits) const {
  switch (type_) {
    case Type::Null: out += "null"; return;
    case Type::Bool: out += bool_ ? "true" : "false"; return;
    case Type::Integer: out += std::to_string(integer_); return;
    case Type::Number: out += json_number(number_, digits); return;
    case Type::String: out += json_quote(string_); return;
    case Type::Array:
    case Type::Object: {
      const bool obj = type_ == Type::Object;
      out += obj ? '{' : '[';
      if (items_.empty()) {
        out += obj ? '}' : ']';
        return;
      }
      for (std::size_t i = 0; i < items_.size(); ++i) {
        if (i > 0) out += ',';
        newline(out, indent, level + 1);
        if (obj) {
          out += json_quote(keys_[i]);
          out += indent > 0 ? ": " : ":";
        }
        items_[i].dump_to(out, indent, level + 1, digits);
      }
      newline(out, indent, level);
      out += obj ? '}' : ']';
      return;
    }
  }
}

namespace {

// Recursive descent over the text; `pos` is the next unread byte.
class Parser {
 public:
  Parser(std::string_view text, const std::string& what) : text_(text), what_(what) {}

  Json document() {
    Json v = value(0);
    skip_space();
    if (pos_ != text_.size()) fail("unexpected text after the value");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(what_ + ": invalid JSON at byte " + std::to_string(pos_) + ": " + why);
  }

  void skip_space() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\n' || text_[pos_] == '\r' || text_[pos_] == '\t'))
      ++pos_;
  }

  char peek() {
    skip_space();
    if (pos_ >= text_.size()) fail("unexpected end of text");
    return text_[pos_];
  }

  void expect(char c) {
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++pos_;
  }

  void literal(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) fail("unknown literal");
    pos_ += word.size();
  }

  Json value(int depth) {
    if (depth > 256) fail("nested deeper than 256 levels");
    const char c = peek();
    if (c == '{') return object(depth);
    if (c == '[') return array(depth);
    if (c == '"') return Json(string());
    if (c == 't') { literal("true"); return Json(true); }
    if (c == 'f') { literal("false"); return Json(false); }
    if (c == 'n') { literal("null"); return Json(); }
    if (c == '-' || (c >= '0' && c <= '9')) return number();
    fail(std::string("unexpected character '") + c + "'");
  }

  Json object(int depth) {
    expect('{');
    Json o = Json::object();
    if (peek() == '}') { ++pos_; return o; }
    for (;;) {
      if (peek() != '"') fail("expected a key string");
      std::string key = string();
      expect(':');
      o.set(key, value(depth + 1));
      if (peek() == ',') { ++pos_; continue; }
      expect('}');
      return o;
    }
  }

  Json array(int depth) {
    expect('[');
    Json a = Json::array();
    if (peek() == ']') { ++pos_; return a; }
    for (;;) {
      a.push_back(value(depth + 1));
      if (peek() == ',') { ++pos_; continue; }
      expect(']');
      return a;
    }
  }

  unsigned hex4() {
    if (pos_ + 4 > text_.size()) fail("truncated \\u escape");
    unsigned v = 0;
    for (int i = 0; i < 4; ++i) {
      const char h = text_[pos_++];
      v <<= 4;
      if (h >= '0' && h <= '9') v |= static_cast<unsigned>(h - '0');
      else if (h >= 'a' && h <= 'f') v |= static_cast<unsigned>(h - 'a' + 10);
      else if (h >= 'A' && h <= 'F') v |= static_cast<unsigned>(h - 'A' + 10);
      else fail("bad hex digit in \\u escape");
    }
    return v;
  }

  static void append_utf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  std::string string() {
    ++pos_;  // the opening quote (checked by the caller)
    std::string out;
    for (;;) {
      if (pos_ >= text_.size()) fail("unterminated string");
      const char c = text_[pos_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= text_.size()) fail("unterminated escape");
      const char e = text_[pos_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned cp = hex4();
          if (cp >= 0xD800 && cp < 0xDC00) {  // a surrogate pair
            if (text_.substr(pos_, 2) != "\\u") fail("lone high surrogate");
            pos_ += 2;
            const unsigned lo = hex4();
            if (lo < 0xDC00 || lo >= 0xE000) fail("bad low surrogate");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          } else if (cp >= 0xDC00 && cp < 0xE000) {
            fail("lone low surrogate");
          }
          append_utf8(out, cp);
          break;
        }
        default: fail("unknown escape");
      }
    }
  }

  Json number() {
    const std::size_t start = pos_;
    auto digits = [&] {
      const std::size_t from = pos_;
      while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') ++pos_;
      return pos_ - from;
    };
    if (text_[pos_] == '-') ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '0') ++pos_;
    else if (digits() == 0) fail("expected a digit");
    bool integral = true;
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      integral = false;
      if (digits() == 0) fail("expected a digit after '.'");
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      integral = false;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
      if (digits() == 0) fail("expected a digit in the exponent");
    }
    const char* first = text_.data() + start;
    const char* last = text_.data() + pos_;
    if (integral) {
      std::int64_t i = 0;
      const auto r = std::from_chars(first, last, i);
      if (r.ec == std::errc() && r.ptr == last) {
        if (i == 0 && *first == '-') return Json(-0.0);  // keep the sign a double -0 was written with
        return Json(i);
      }
    }
    double x = 0;
    const auto r = std::from_chars(first, last, x);
    if (r.ec == std::errc::result_out_of_range)  // from_chars leaves x alone: overflow to ±inf, underflow to 0
      return Json(std::strtod(std::string(first, last).c_str(), nullptr));
    if (r.ec != std::errc() || r.ptr != last) fail("bad number");
    return Json(x);
  }

  std::string_view text_;
  const std::string& what_;
  std::size_t pos_ = 0;
};

}  // namespace

Json Json::parse(std::string_view text, const std::string& what) { return Parser(text, what).document(); }

}  // namespace polydem
