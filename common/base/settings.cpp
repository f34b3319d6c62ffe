#include "common/base/settings.hpp"

#include "common/base/error.hpp"

#include <algorithm>
#include <sstream>

namespace wb {
namespace {
std::string valueString(const Setting& s) {
  switch (s.kind) {
    case Setting::Kind::Float: {
      std::ostringstream o;
      o << *static_cast<float*>(s.value);
      return o.str();
    }
    case Setting::Kind::Int:
      return std::to_string(*static_cast<int*>(s.value));
    case Setting::Kind::Bool:
      return *static_cast<bool*>(s.value) ? "true" : "false";
    case Setting::Kind::Choice:
      return s.choices[*static_cast<int*>(s.value)];
  }
  return "";
}
std::string accepted(const Setting& s) {
  std::ostringstream o;
  switch (s.kind) {
    case Setting::Kind::Float:
      o << "a number in [" << s.min << ", " << s.max << "]";
      break;
    case Setting::Kind::Int:
      o << "an integer in [" << int(s.min) << ", " << int(s.max) << "]";
      break;
    case Setting::Kind::Bool:
      o << "true or false";
      break;
    case Setting::Kind::Choice:
      o << "one of";
      for (const auto& c : s.choices) o << " " << c;
  }
  return o.str();
}
}  // namespace

void Settings::add(const std::string& n, float& v, float min, float max, const std::string& help) {
  settings_.push_back({n, help, Setting::Kind::Float, &v, min, max, {}, {}});
}
void Settings::add(const std::string& n, int& v, int min, int max, const std::string& help) {
  settings_.push_back({n, help, Setting::Kind::Int, &v, float(min), float(max), {}, {}});
}
void Settings::add(const std::string& n, bool& v, const std::string& help) {
  settings_.push_back({n, help, Setting::Kind::Bool, &v, 0, 1, {}, {}});
}
void Settings::addChoice(const std::string& n, int& v, std::vector<std::string> choices, const std::string& help) {
  settings_.push_back({n, help, Setting::Kind::Choice, &v, 0, float(choices.size() - 1), std::move(choices), {}});
}

const Setting& Settings::find(const std::string& name) const {
  for (const auto& s : settings_)
    if (s.name == name) return s;
  throw UsageError("unknown setting '" + name + "'; --list-settings shows the settings of this lab");
}

void Settings::assign(const std::string& a) {
  const auto eq = a.find('=');
  if (eq == std::string::npos) throw UsageError("--set expects key=value, got '" + a + "'");
  const Setting& s = find(a.substr(0, eq));
  const std::string text = a.substr(eq + 1);
  auto bad = [&] { return UsageError("bad value '" + text + "' for " + s.name + ": expected " + accepted(s)); };
  std::istringstream in(text);
  switch (s.kind) {
    case Setting::Kind::Float: {
      float v;
      if (!(in >> v) || !in.eof() || v < s.min || v > s.max) throw bad();
      *static_cast<float*>(s.value) = v;
      break;
    }
    case Setting::Kind::Int: {
      int v;
      if (!(in >> v) || !in.eof() || v < s.min || v > s.max) throw bad();
      *static_cast<int*>(s.value) = v;
      break;
    }
    case Setting::Kind::Bool:
      if (text == "true" || text == "1" || text == "on")
        *static_cast<bool*>(s.value) = true;
      else if (text == "false" || text == "0" || text == "off")
        *static_cast<bool*>(s.value) = false;
      else
        throw bad();
      break;
    case Setting::Kind::Choice: {
      auto it = std::find(s.choices.begin(), s.choices.end(), text);
      if (it == s.choices.end()) throw bad();
      *static_cast<int*>(s.value) = int(it - s.choices.begin());
    }
  }
  if (const auto changed = s.changed) changed();  // (a copy: it may replace this list)
}

void Settings::onChange(const std::string& name, std::function<void()> f) {
  const_cast<Setting&>(find(name)).changed = std::move(f);
}

void Settings::include(const Settings& other, const std::function<bool(const Setting&)>& keep) {
  for (const auto& s : other.settings_)
    if (!has(s.name) && keep(s)) settings_.push_back(s);
}

bool Settings::has(const std::string& name) const {
  return std::any_of(settings_.begin(), settings_.end(), [&](const Setting& s) { return s.name == name; });
}

std::string Settings::value(const std::string& name) const { return valueString(find(name)); }

void Settings::list(std::ostream& out) const {
  for (const auto& s : settings_)
    out << "  " << s.name << " = " << valueString(s) << "    (" << accepted(s) << ")\n      " << s.help << "\n";
}

}  // namespace wb
