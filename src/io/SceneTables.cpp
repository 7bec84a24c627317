#include "io/SceneTables.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <fstream>
#include <limits>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "io/SceneSchema.hpp"

namespace og::io::detail {
namespace fs = std::filesystem;

std::string at(const fs::path& file, toml::source_index line) {
  std::string s = file.string();
  if (line > 0) s.append(":").append(std::to_string(line));  // (not ":" + ...: GCC 12 -Wrestrict)
  return s.append(": ");
}

std::string where(const fs::path& file, const toml::node& n) { return at(file, n.source().begin.line); }

double number(const fs::path& file, const toml::node& n, const std::string& key) {
  if (auto v = n.value<double>(); v && n.is_number()) {
    if (!std::isfinite(*v)) throw InputError(where(file, n) + "'" + key + "' must be finite");
    return *v;
  }
  throw InputError(where(file, n) + "'" + key + "' must be a number");
}

std::int64_t integer(const fs::path& file, const toml::node& n, const std::string& key, std::int64_t lo,
                     std::int64_t hi) {
  if (auto v = n.value<std::int64_t>(); v && n.is_integer()) {
    if (*v < lo || *v > hi)
      throw InputError(where(file, n) + "'" + key + "' must be within [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "]");
    return *v;
  }
  throw InputError(where(file, n) + "'" + key + "' must be an integer");
}

std::string text(const fs::path& file, const toml::node& n, const std::string& key) {
  if (auto v = n.value<std::string>(); v && n.is_string()) return *v;
  throw InputError(where(file, n) + "'" + key + "' must be a string");
}

const toml::table& tableOf(const fs::path& file, const toml::node& n, const std::string& name) {
  const toml::table* t = n.as_table();
  if (t == nullptr) throw InputError(where(file, n) + "'" + name + "' must be a table");
  return *t;
}

void applyKeys(const fs::path& file, const toml::table& table, const std::string& section,
               const std::map<std::string, Setter>& keys) {
  for (const auto& [key, value] : table) {
    const std::string k(key.str());
    const auto it = keys.find(k);
    if (it == keys.end())
      throw InputError(at(file, key.source().begin.line) + "unknown key '" + k + "' in " + section);
    it->second(value, k);
  }
}

// --- parsing ---------------------------------------------------------------------------------
namespace {
toml::table fromJson(const nlohmann::json& j, const fs::path& file);

toml::array arrayFromJson(const nlohmann::json& j, const fs::path& file) {
  toml::array a;
  for (const auto& v : j) {
    if (v.is_object()) a.push_back(fromJson(v, file));
    else if (v.is_string()) a.push_back(v.get<std::string>());
    else if (v.is_number_integer()) a.push_back(v.get<std::int64_t>());
    else if (v.is_number()) a.push_back(v.get<double>());
    else if (v.is_boolean()) a.push_back(v.get<bool>());
    else throw InputError(file.string() + ": unsupported JSON array element " + v.dump());
  }
  return a;
}

void insertJson(toml::table& t, const std::string& key, const nlohmann::json& v, const fs::path& file) {
  if (v.is_object()) t.insert(key, fromJson(v, file));
  else if (v.is_array()) t.insert(key, arrayFromJson(v, file));
  else if (v.is_string()) t.insert(key, v.get<std::string>());
  else if (v.is_number_integer()) t.insert(key, v.get<std::int64_t>());
  else if (v.is_number()) t.insert(key, v.get<double>());
  else if (v.is_boolean()) t.insert(key, v.get<bool>());
  else throw InputError(file.string() + ": '" + key + "' has an unsupported JSON value (null?)");
}

toml::table fromJson(const nlohmann::json& j, const fs::path& file) {
  if (!j.is_object()) throw InputError(file.string() + ": expected a JSON object");
  toml::table t;
  for (const auto& [key, value] : j.items()) insertJson(t, key, value, file);
  return t;
}

InputError tomlError(const fs::path& file, const toml::parse_error& e) {
  // toml++ says "File could not be opened for reading" for missing/unreadable files.
  return InputError(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                    std::string(e.description()));
}
}  // namespace

toml::table parseTomlOrJson(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".json") {
    std::ifstream in(file);
    if (!in) throw InputError(file.string() + ": cannot open for reading");
    try {
      return fromJson(nlohmann::json::parse(in), file);
    } catch (const nlohmann::json::parse_error& e) {
      throw InputError(file.string() + ": JSON syntax error at byte " + std::to_string(e.byte));
    }
  }
  try {
    return toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw tomlError(file, e);
  }
}

toml::table parseTomlText(const std::string& text, const fs::path& file, int firstLine) {
  // Blank lines in front make toml++'s line numbers those of the enclosing file.
  const std::string shifted = std::string(static_cast<std::size_t>(std::max(firstLine - 1, 0)), '\n') + text;
  try {
    return toml::parse(shifted, file.string());
  } catch (const toml::parse_error& e) {
    throw tomlError(file, e);
  }
}

// --- the scene by its schema -------------------------------------------------------------------
namespace {

// The value of `n` in the field's C++ type; its type and range checked.
FieldValue readValue(const fs::path& file, const SceneField& f, const toml::node& n, const std::string& key) {
  FieldValue v;
  switch (f.type) {
    case FieldType::Number: v = number(file, n, key); break;
    case FieldType::Integer:
      v = integer(file, n, key, std::numeric_limits<std::int64_t>::min(),
                  std::numeric_limits<std::int64_t>::max());
      break;
    case FieldType::Text:
    case FieldType::Time: v = text(file, n, key); break;
    case FieldType::TextList: {
      const toml::array* list = n.as_array();
      if (list == nullptr) throw InputError(where(file, n) + "'" + key + "' must be an array of strings");
      std::vector<std::string> items;
      for (const toml::node& item : *list) items.push_back(text(file, item, key));
      v = std::move(items);
      break;
    }
    case FieldType::Triple: {
      const toml::array* a = n.as_array();
      if (a == nullptr || a->size() != 3)
        throw InputError(where(file, n) + "'" + key + "' must be an array of 3 numbers");
      glm::dvec3 c;
      for (int i = 0; i < 3; ++i) c[i] = number(file, *a->get(static_cast<std::size_t>(i)), key);
      v = c;
      break;
    }
    case FieldType::Samples:
      if (n.is_string() && n.value<std::string>() == "auto") v = std::int64_t{kAutoSamples};
      else if (n.is_integer() && *n.value<std::int64_t>() != kAutoSamples) v = *n.value<std::int64_t>();
      else throw InputError(where(file, n) + "'" + key + "' must be " + std::string(kSampleCountChoices));
      break;
  }
  if (auto problem = checkField(f, v, true)) throw InputError(where(file, n) + *problem);
  return v;
}

// The field of `section` named `key` (or one of its older names), or nullptr.
const SceneField* fieldOf(std::string_view section, std::string_view key) {
  for (const SceneField& f : sceneSchema()) {
    if (f.section != section) continue;
    if (f.key == key || std::find(f.aliases.begin(), f.aliases.end(), key) != f.aliases.end()) return &f;
  }
  return nullptr;
}

bool isSection(std::string_view name) {
  const auto& schema = sceneSchema();
  return std::any_of(schema.begin(), schema.end(), [&](const SceneField& f) { return f.section == name; });
}

void readSection(const fs::path& file, const toml::table& t, const std::string& section,
                 const std::string& shown, SceneSettings& s) {
  for (const auto& [key, value] : t) {
    const std::string k(key.str());
    const SceneField* f = fieldOf(section, k);
    if (f == nullptr)
      throw InputError(at(file, key.source().begin.line) + "unknown key '" + k + "' in [" + shown + "]");
    f->set(s, readValue(file, *f, value, k));
  }
}

void readPathScene(const fs::path& file, const toml::table& scene, SceneSettings& s) {
  for (const auto& [key, value] : scene) {
    const std::string k(key.str());
    if (value.is_table() && isSection(k)) {
      if (k == "camera")
        throw InputError(where(file, value) + "[scene.camera]: a path's camera comes from its keyframes");
      readSection(file, *value.as_table(), k, "scene." + k, s);
      continue;
    }
    const auto& schema = sceneSchema();
    const auto f = std::find_if(schema.begin(), schema.end(), [&](const SceneField& x) { return x.legacyPathKey == k; });
    if (f == schema.end())
      throw InputError(at(file, key.source().begin.line) + "unknown key '" + k + "' in [scene]");
    f->set(s, readValue(file, *f, value, k));
  }
}

}  // namespace

void readSceneTables(const fs::path& file, const toml::table& table, SceneSettings& s, SceneForm form) {
  if (form == SceneForm::PathScene) return readPathScene(file, table, s);
  for (const auto& [sectionKey, node] : table) {
    const std::string section(sectionKey.str());
    if (!isSection(section))
      throw InputError(at(file, sectionKey.source().begin.line) + "unknown section [" + section + "]");
    readSection(file, tableOf(file, node, section), section, section, s);
  }
}

nlohmann::json sceneJson(const SceneSettings& s, bool withCamera) {
  const SceneSettings earth;
  bool customAtmosphere = false;
  for (const SceneField& f : sceneSchema())
    customAtmosphere |= f.section == "atmosphere" && f.get(s) != f.get(earth);
  nlohmann::json j = nlohmann::json::object();
  for (const SceneField& f : sceneSchema()) {
    if ((f.section == "camera" && !withCamera) || (f.section == "atmosphere" && !customAtmosphere)) continue;
    const FieldValue v = f.get(s);
    if (std::holds_alternative<std::monostate>(v)) continue;  // an optional setting not given
    nlohmann::json& out = j[std::string(f.section)][std::string(f.key)];
    if (f.type == FieldType::Samples && std::get<std::int64_t>(v) == kAutoSamples) out = "auto";
    else if (const double* d = std::get_if<double>(&v)) out = *d;
    else if (const std::int64_t* i = std::get_if<std::int64_t>(&v)) out = *i;
    else if (const std::string* t = std::get_if<std::string>(&v)) out = *t;
    else if (const auto* list = std::get_if<std::vector<std::string>>(&v)) out = *list;
    else if (const glm::dvec3* c = std::get_if<glm::dvec3>(&v)) out = {c->x, c->y, c->z};
  }
  return j;
}

std::string tomlNumber(double v) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

std::string tomlString(const std::string& v) {
  std::string out = "\"";
  for (const char c : v) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7F) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04X", static_cast<unsigned>(u));
      out += esc;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

void writeTextFile(const fs::path& file, const std::string& text) {
  writeFileAtomically(file, [&](const fs::path& tmp) {
    std::ofstream out(tmp);
    out << text;
    if (!out.flush()) throw InputError(file.string() + ": cannot write");
  });
}

}  // namespace og::io::detail
