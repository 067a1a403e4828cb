// Checked access to a scene's TOML values: each accessor returns the value
// or throws a SceneError placed at the offending node, in the form of
// scene.h ("FILE:LINE:COL: what is wrong; what is expected"). The section
// readers (sections.h) build on it.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <vector>

#include "scene/scene.h"

namespace vivp::scene::detail {

// "a string", "a whole number", … : what the node holds, for messages.
std::string TypeName(const toml::node& n);

class TomlReader {
 public:
  explicit TomlReader(std::string source) : source_(std::move(source)) {}

  const std::string& source() const { return source_; }

  // "FILE:LINE:COL: " (line and column at least 1).
  std::string Where(int line, int column) const;
  std::string Where(const toml::node& n) const;
  [[noreturn]] void Fail(const toml::node& at, const std::string& what,
                         const std::string& expected) const;
  [[noreturn]] void Fail(int line, int column, const std::string& what,
                         const std::string& expected) const;

  // Fails at the first key of `t` not in `valid`; `where` names the table.
  void CheckKeys(const toml::table& t, const std::string& where,
                 const std::vector<std::string>& valid) const;
  // The table [name] of `root`; an empty one when it is absent and optional.
  const toml::table& Table(const toml::table& root, const std::string& name,
                           bool required) const;
  const toml::node& Require(const toml::table& t, const std::string& table,
                            const std::string& key,
                            const std::string& expected) const;

  std::string String(const toml::node& n, const std::string& key,
                     const std::string& expected) const;
  std::string Choice(const toml::node& n, const std::string& key,
                     const std::vector<std::string>& valid) const;
  double Number(const toml::node& n, const std::string& key,
                const std::string& expected) const;
  long long Whole(const toml::node& n, const std::string& key,
                  long long minimum, const std::string& expected) const;
  std::vector<double> Numbers(const toml::node& n, const std::string& key,
                              std::size_t count,
                              const std::string& expected) const;

 private:
  std::string source_;
};

}  // namespace vivp::scene::detail
