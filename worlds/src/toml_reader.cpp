#include "frob/worlds/toml_reader.hpp"

#include <algorithm>
#include <cmath>

namespace frob::worlds {

bool TomlReader::parse(std::string_view text, toml::table& root) {
  try {
    root = toml::parse(text, file_);
    return true;
  } catch (const toml::parse_error& e) {
    error_ = where(static_cast<int>(e.source().begin.line)) + "syntax error: " + std::string(e.description());
    return false;
  }
}

std::string TomlReader::where(int l) const { return l > 0 ? file_ + ":" + std::to_string(l) + ": " : file_ + ": "; }

bool TomlReader::fail(int l, const std::string& field, const std::string& message) {
  if (error_.empty()) error_ = where(l) + field + ": " + message;
  return false;
}

bool TomlReader::onlyKeys(const toml::table& t, const std::string& prefix, std::initializer_list<std::string_view> allowed) {
  for (auto&& [k, v] : t) {
    if (std::find(allowed.begin(), allowed.end(), k.str()) != allowed.end()) continue;
    std::string list;
    for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    return fail(static_cast<int>(k.source().begin.line), prefix + std::string(k.str()), "unknown key (expected one of " + list + ")");
  }
  return true;
}

bool TomlReader::number(const toml::node& n, const std::string& field, double& out) {
  if (auto f = n.as_floating_point())
    out = f->get();
  else if (auto i = n.as_integer())
    out = static_cast<double>(i->get());
  else
    return fail(n, field, "expected a number");
  if (!std::isfinite(out)) return fail(n, field, "expected a finite number");
  return true;
}

bool TomlReader::integer(const toml::node& n, const std::string& field, long long lo, long long hi, long long& out) {
  auto i = n.as_integer();
  if (!i) return fail(n, field, "expected an integer");
  if (i->get() < lo || i->get() > hi) return fail(n, field, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  out = i->get();
  return true;
}

bool TomlReader::integer(const toml::node& n, const std::string& field, long long lo, long long hi, int& out) {
  long long v = 0;
  if (!integer(n, field, lo, hi, v)) return false;
  out = static_cast<int>(v);
  return true;
}

bool TomlReader::point(const toml::node& n, const std::string& field, Point2& out) {
  auto a = n.as_array();
  if (!a || a->size() != 2 || !(*a)[0].is_number() || !(*a)[1].is_number()) return fail(n, field, "expected [x, y]");
  return number((*a)[0], field, out.x()) && number((*a)[1], field, out.y());
}

bool TomlReader::string(const toml::node& n, const std::string& field, std::string& out) {
  auto s = n.as_string();
  if (!s) return fail(n, field, "expected a string");
  out = s->get();
  return true;
}

bool TomlReader::boolean(const toml::node& n, const std::string& field, bool& out) {
  auto b = n.as_boolean();
  if (!b) return fail(n, field, "expected true or false");
  out = b->get();
  return true;
}

const toml::table* TomlReader::table(const toml::node& n, const std::string& field) {
  auto t = n.as_table();
  if (!t) fail(n, field, "expected a table");
  return t;
}

bool TomlReader::optNumber(const toml::table& t, std::string_view key, const std::string& field, double& out, double unit) {
  const toml::node* n = t.get(key);
  if (!n) return true;
  if (!number(*n, field, out)) return false;
  out *= unit;
  return true;
}

bool TomlReader::optInteger(const toml::table& t, std::string_view key, const std::string& field, long long lo, long long hi, int& out) {
  const toml::node* n = t.get(key);
  return !n || integer(*n, field, lo, hi, out);
}

bool TomlReader::optPoint(const toml::table& t, std::string_view key, const std::string& field, Point2& out) {
  const toml::node* n = t.get(key);
  return !n || point(*n, field, out);
}

bool TomlReader::optString(const toml::table& t, std::string_view key, const std::string& field, std::string& out) {
  const toml::node* n = t.get(key);
  return !n || string(*n, field, out);
}

}  // namespace frob::worlds
