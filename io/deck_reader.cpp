#include "io/deck_reader.hpp"

#include "core/number_text.hpp"

namespace polydem::deck_reader {

std::string format_number(double v) { return shortest_text(v); }

std::string in_quotes(std::string_view s) {
  std::string out;
  out.reserve(s.size() + 2);
  out.append(1, '"').append(s).append(1, '"');
  return out;
}

std::string join_quoted(std::span<const std::string_view> items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + in_quotes(s);
  return out;
}

std::string join(std::span<const std::string_view> items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + std::string(s);
  return out;
}

bool contains(std::span<const std::string_view> items, std::string_view s) {
  return std::find(items.begin(), items.end(), s) != items.end();
}

std::string indexed(std::string_view base, std::size_t one_based) {
  return std::string(base) + "[" + std::to_string(one_based) + "]";
}

std::string describe(const toml::node& n) {
  if (const auto* s = n.as_string()) return "string " + in_quotes(s->get());
  if (const auto* i = n.as_integer()) return "integer " + std::to_string(i->get());
  if (const auto* f = n.as_floating_point()) return "float " + format_number(f->get());
  if (const auto* b = n.as_boolean()) return std::string("boolean ") + (b->get() ? "true" : "false");
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date/time";
}

const toml::table* section_table(const Deck& deck, std::string_view name) {
  const toml::node* n = deck.root().get(name);
  if (!n) return nullptr;
  if (const auto* t = n->as_table()) return t;
  deck.fail(std::string(name), n, "must be a table: write [" + std::string(name) + "] (got " + describe(*n) + ")");
}

std::vector<const toml::table*> section_tables(const Deck& deck, std::string_view name) {
  std::vector<const toml::table*> out;
  const toml::node* n = deck.root().get(name);
  if (!n) return out;
  const std::string how = "must be an array of tables: write [[" + std::string(name) + "]]";
  const auto* arr = n->as_array();
  if (!arr) deck.fail(std::string(name), n, how + " (got " + describe(*n) + ")");
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const auto* t = arr->get(i)->as_table();
    if (!t) deck.fail(indexed(name, i + 1), arr->get(i), how + " (got " + describe(*arr->get(i)) + ")");
    out.push_back(t);
  }
  return out;
}

const toml::table& table_or_empty(const Deck& deck, std::string_view name) {
  static const toml::table empty;
  const toml::table* t = section_table(deck, name);
  return t ? *t : empty;
}

void Deck::fail(const std::string& key, const toml::node* at, const std::string& what) const {
  long line = at ? static_cast<long>(at->source().begin.line) : 0;
  if (at == &root_ && line == 0) line = 1;
  const bool from_override =
      overridden(key) || (at && at->source().path && *at->source().path == kOverrideSource) || line == 0;
  if (from_override) throw DeckError(file_ + ": --set key '" + key + "': " + what);
  throw DeckError(file_ + ":" + std::to_string(line) + ": key '" + key + "': " + what);
}

}  // namespace polydem::deck_reader
