#include "roadscale/util/yaml_file.h"

#include <map>
#include <set>
#include <utility>
#include <vector>

#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"

namespace roadscale {
namespace {

// Walks every mapping of the document once, checking its keys: names, each once. Aliases make a
// node reachable many times (and nested aliases exponentially many), so collections are visited
// once each, known by where they start and what they are: two different collections cannot share
// both.
void CheckKeys(const YAML::Node& root, const std::string& path) {
  std::set<std::pair<int, int>> visited;
  std::vector<YAML::Node> pending = {root};
  while (!pending.empty()) {
    const YAML::Node node = pending.back();
    pending.pop_back();
    if (!node.IsMap() && !node.IsSequence()) continue;
    if (!visited.insert({node.Mark().pos, static_cast<int>(node.Type())}).second) continue;
    if (node.IsSequence()) {
      for (const YAML::Node& item : node) pending.push_back(item);
      continue;
    }
    std::map<std::string, int> first_line;
    for (const auto& entry : node) {
      pending.push_back(entry.second);
      if (!entry.first.IsScalar()) {
        // An empty key (": 3") or a list or mapping as a key: no reader has a use for one,
        // and each would have to guard its key conversions against it.
        int line = YamlLine(entry.first.Mark());
        if (line == 0) line = YamlLine(entry.second.Mark());
        if (line == 0) line = YamlLine(node.Mark());
        ThrowFileError(path, line,
                       entry.first.IsNull() ? "a key is empty (expected 'name: value')"
                                            : "a key must be a name, not a list or a mapping");
      }
      const int line = YamlLine(entry.first.Mark());
      const auto [it, inserted] = first_line.emplace(entry.first.Scalar(), line);
      if (!inserted) {
        ThrowFileError(path, line,
                       "key '" + entry.first.Scalar() +
                           "' appears twice in one mapping (first on " + "line " +
                           std::to_string(it->second) + ")");
      }
    }
  }
}

}  // namespace

int YamlLine(const YAML::Mark& mark) { return mark.is_null() ? 0 : mark.line + 1; }

YAML::Node ParseYaml(const std::string& text, const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    ThrowFileError(path, YamlLine(e.mark), "invalid YAML: " + e.msg);
  }
  CheckKeys(root, path);
  return root;
}

YAML::Node LoadYamlFile(const std::string& path, const std::string& what) {
  return ParseYaml(ReadInputFile(path, what), path);
}

}  // namespace roadscale
