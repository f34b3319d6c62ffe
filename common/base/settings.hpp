/// @file settings.hpp
/// Named lab settings: the same values the UI edits, `--set key=value` assigns and
/// `--list-settings` prints. Labs register their tunables once, with a range and a one-line help.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace wb {

/// One tunable: a name such as "shadow.map_size", a pointer to the lab's member, and its limits.
struct Setting {
  /// The value type behind `value`.
  enum class Kind { Float, Int, Bool, Choice };
  std::string name;                  ///< dotted name used by --set and the UI
  std::string help;                  ///< one line, shown by --list-settings and as a tooltip
  Kind kind;                         ///< value type
  void* value;                       ///< points at the lab's member
  float min = 0;                     ///< lower bound for Float and Int
  float max = 1;                     ///< upper bound for Float and Int
  std::vector<std::string> choices;  ///< names for Choice (the int is the index)
  std::function<void()> changed;     ///< called after assign() sets it (see Settings::onChange)
};

/// The settings registry of one lab.
class Settings {
 public:
  /// Registers a float in [min, max].
  void add(const std::string& name, float& v, float min, float max, const std::string& help);
  /// Registers an int in [min, max].
  void add(const std::string& name, int& v, int min, int max, const std::string& help);
  /// Registers a bool (accepts true/false/1/0/on/off).
  void add(const std::string& name, bool& v, const std::string& help);
  /// Registers an int chosen by name from `choices`.
  void addChoice(const std::string& name, int& v, std::vector<std::string> choices, const std::string& help);

  /// Calls `f` after every assign() of setting `name`, so that a host can follow it at once (the
  /// showcase adopts the chosen technique's settings before the next --set is applied).
  void onChange(const std::string& name, std::function<void()> f);
  /// Appends a copy of every setting of `other` that `keep` accepts and whose name is not here yet;
  /// the copies point at `other`'s variables (the showcase shows a hosted lab's settings as its own).
  void include(const Settings& other, const std::function<bool(const Setting&)>& keep);
  /// Applies "key=value"; throws wb::UsageError saying what is accepted.
  void assign(const std::string& assignment);
  /// True if a setting of that name is registered.
  bool has(const std::string& name) const;
  /// The current value of a setting as text (what assign() accepts); throws wb::UsageError if unknown.
  std::string value(const std::string& name) const;
  /// Prints every setting with its current value, range and help.
  void list(std::ostream& out) const;
  /// All settings in registration order.
  const std::vector<Setting>& all() const { return settings_; }

 private:
  const Setting& find(const std::string& name) const;
  std::vector<Setting> settings_;
};

}  // namespace wb
