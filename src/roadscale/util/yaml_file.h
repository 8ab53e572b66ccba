#pragma once

#include <string>

#include <yaml-cpp/yaml.h>

namespace roadscale {

// Parses `text`, the contents of `path`, as one YAML document. Throws Error naming the file
// and the line on a syntax error, and on a key that appears twice in one mapping: yaml-cpp
// keeps both, its lookups take the first and a loop over the mapping reads both, so `fx`
// twice or a `Scale:` block twice would otherwise pass silently with one of them ignored.
// Every key must be a name: an empty key or a list or mapping as a key is an error too.
YAML::Node ParseYaml(const std::string& text, const std::string& path);

// ParseYaml of the file (ReadInputFile: "PATH: cannot open WHAT: reason" when it cannot be read).
YAML::Node LoadYamlFile(const std::string& path, const std::string& what);

// yaml-cpp counts lines from 0 and marks "no position" with -1; ThrowFileError wants 1-based
// lines and 0 for none.
int YamlLine(const YAML::Mark& mark);

}  // namespace roadscale
