#include "io/json.hpp"

#include <charconv>
#include <cmath>
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

std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);  // shortest round trip
  return std::string(buf, r.ptr);
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

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  return out;
}

void Json::dump_to(std::string& out, int indent, int level) const {
  switch (type_) {
    case Type::Null: out += "null"; return;
    case Type::Bool: out += bool_ ? "true" : "false"; return;
    case Type::Integer: out += std::to_string(integer_); return;
    case Type::Number: out += json_number(number_); return;
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
        items_[i].dump_to(out, indent, level + 1);
      }
      newline(out, indent, level);
      out += obj ? '}' : ']';
      return;
    }
  }
}

}  // namespace polydem
