#include "roadscale/util/yaml_file.h"

#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::string YamlErrorOf(const std::string& text) {
  try {
    ParseYaml(text, "c.yaml");
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(YamlFile, ParsesAValidDocument) {
  const YAML::Node root = ParseYaml("Camera:\n  fx: 1\n  fy: 2\nlist: [1, 2]\n", "c.yaml");
  EXPECT_EQ(root["Camera"]["fy"].as<int>(), 2);
}

TEST(YamlFile, ADuplicateKeyIsAnErrorNamingBothLines) {
  EXPECT_EQ(YamlErrorOf("Camera:\n  fx: 1\n  fy: 2\n  fx: 3\n"),
            "c.yaml:4: key 'fx' appears twice in one mapping (first on line 2)");
}

TEST(YamlFile, ARepeatedBlockIsAnError) {
  EXPECT_EQ(YamlErrorOf("Scale:\n  a: 1\nFrontend:\n  b: 2\nScale:\n  c: 3\n"),
            "c.yaml:5: key 'Scale' appears twice in one mapping (first on line 1)");
}

TEST(YamlFile, DuplicatesInsideSequencesAndFlowMappings) {
  EXPECT_EQ(YamlErrorOf("items:\n  - {a: 1, a: 2}\n"),
            "c.yaml:2: key 'a' appears twice in one mapping (first on line 2)");
  // The same key in two different mappings is fine.
  EXPECT_EQ(YamlErrorOf("a: {x: 1}\nb: {x: 2}\n"), "no error");
}

TEST(YamlFile, KeysMustBeNames) {
  // Found by the fuzzer: the config reader converted every key to a string, and an empty key
  // escaped as YAML::TypedBadConversion (an "internal error").
  EXPECT_EQ(YamlErrorOf("Scale:\n  : 3\n"), "c.yaml:2: a key is empty (expected 'name: value')");
  EXPECT_EQ(YamlErrorOf("? [a, b]\n: 1\n"),
            "c.yaml:1: a key must be a name, not a list or a mapping");
}

TEST(YamlFile, SyntaxErrorNamesTheLine) {
  EXPECT_EQ(YamlErrorOf("a: 1\nb: [1, 2\n").rfind("c.yaml:", 0), 0u);
  EXPECT_NE(YamlErrorOf("a: 1\nb: [1, 2\n").find("invalid YAML"), std::string::npos);
}

TEST(YamlFile, NestedAliasesAreWalkedOnce) {
  // Each level refers to the one before ten times: 10^8 paths to the first mapping, which a
  // walk that followed every alias would never finish.
  std::string text = "l0: &l0 {k: v}\n";
  for (int level = 1; level <= 8; ++level) {
    text += "l" + std::to_string(level) + ": &l" + std::to_string(level) + " [";
    for (int i = 0; i < 10; ++i) text += (i ? ", *l" : "*l") + std::to_string(level - 1);
    text += "]\n";
  }
  EXPECT_EQ(YamlErrorOf(text), "no error");
}

TEST(YamlFile, LoadYamlFileNamesAnUnreadableFile) {
  testing::TempDir dir;
  try {
    LoadYamlFile(dir.path().string(), "config file");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              dir.path().string() + ": cannot open config file: is a directory");
  }
}

}  // namespace
}  // namespace roadscale
