// The case schema (casefile/case_schema.hpp, casefile/case_fields.hpp): every bundled case reads
// back to the same case from its resolved form (the writer derived from the same tables as the
// reader), every field is documented, the choice tables are one-to-one, and the reader's
// unknown-key and not-applicable checks come from the tables.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "casefile/case_config.hpp"
#include "casefile/case_fields.hpp"
#include "read_case_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using sf_test::ReadCase;

std::vector<fs::path> bundled_cases() {
  std::vector<fs::path> cases;
  for (const auto& entry : fs::directory_iterator(fs::path(SF_SOURCE_DIR) / "cases")) {
    if (fs::exists(entry.path() / "case.toml")) {
      cases.push_back(entry.path() / "case.toml");
    }
  }
  std::sort(cases.begin(), cases.end());
  return cases;
}

// The resolved case of every bundled case is a case that resolves to the same text: the writer
// writes every key the reader read (a key the writer forgot, or wrote in a form the reader takes
// differently, changes the second text). Written in another folder, so its paths must be absolute.
TEST_F(ReadCase, EveryBundledCaseResolvesToATextThatResolvesToItself) {
  const std::vector<fs::path> cases = bundled_cases();
  ASSERT_GE(cases.size(), 20u);
  for (const fs::path& file : cases) {
    SCOPED_TRACE(file.string());
    const std::string resolved = sf::format_resolved_case(sf::read_case(file));
    const fs::path again_file =
        write_case(resolved, "resolved/" + file.parent_path().filename().string() + ".toml");
    std::string again = sf::format_resolved_case(sf::read_case(again_file));
    // The header names the file it was read from; the rest must be equal.
    const auto body = [](const std::string& text) { return text.substr(text.find("\ntitle")); };
    EXPECT_EQ(body(again), body(resolved));
  }
}

// Each section's table documents every key: a type, a default (or "required") and what is
// allowed; and a key appears twice in a table only under exclusive conditions (Swift's and
// Ludwik's n), never unconditionally.
TEST(CaseSchema, EveryFieldIsDocumented) {
  const std::vector<sf::SchemaSection> sections = sf::case_schema();
  EXPECT_GE(sections.size(), 17u);
  for (const sf::SchemaSection& section : sections) {
    SCOPED_TRACE(section.name);
    EXPECT_FALSE(section.fields.empty());
    for (const sf::FieldDoc& d : section.fields) {
      SCOPED_TRACE(d.key);
      EXPECT_FALSE(d.key.empty());
      EXPECT_FALSE(d.type.empty());
      EXPECT_FALSE(d.default_text.empty());
      EXPECT_FALSE(d.allowed.empty());
    }
  }
  std::multiset<std::string> hardening_keys;
  for (const auto& f : sf::hardening_fields()) {
    hardening_keys.insert(f.doc.key);
    if (f.doc.key != "law") {
      EXPECT_TRUE(static_cast<bool>(f.applies)) << f.doc.key << " must name its laws";
    }
  }
  EXPECT_EQ(hardening_keys.count("n"), 2u);  // Swift's and Ludwik's
}

// The Markdown tables carry the marker lines scripts/update_case_docs.py finds them by.
TEST(CaseSchema, MarkdownHasOneMarkedTablePerSection) {
  const std::string markdown = sf::case_schema_markdown();
  for (const sf::SchemaSection& section : sf::case_schema()) {
    const std::string begin = "<!-- schema: " + section.name + " -->\n| key | type | default |";
    EXPECT_NE(markdown.find(begin), std::string::npos) << section.name;
  }
  // A '|' inside a cell is escaped: |slip speed| in the friction decay.
  EXPECT_NE(markdown.find("\\|slip speed\\|"), std::string::npos);
}

template <typename E>
void expect_one_to_one(std::span<const sf::Choice<E>> table) {
  std::set<std::string_view> names;
  std::set<E> values;
  for (const sf::Choice<E>& c : table) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_TRUE(values.insert(c.value).second) << c.name;
    EXPECT_EQ(sf::find_choice(table, c.name), c.value);
    EXPECT_EQ(sf::choice_name(table, c.value), c.name);
  }
  EXPECT_FALSE(sf::find_choice(table, "no such name").has_value());
}

TEST(CaseSchema, ChoiceTablesAreOneToOne) {
  expect_one_to_one<sf::ContactSearchKind>(sf::kContactSearchNames);
  expect_one_to_one<sf::ContactProjection>(sf::kContactProjectionNames);
  expect_one_to_one<sf::ThroughThicknessRule>(sf::kThroughThicknessRuleNames);
  expect_one_to_one<sf::ShellFormulation>(sf::kShellFormulationNames);
  expect_one_to_one<sf::HourglassForm>(sf::kHourglassFormNames);
  expect_one_to_one<sf::BlankMeshing>(sf::kBlankMeshingNames);
  expect_one_to_one<sf::MaterialConfig::Type>(sf::kMaterialTypeNames);
  expect_one_to_one<sf::HardeningConfig::Law>(sf::kHardeningLawNames);
}

// An unknown key lists the section's keys: exactly those of its table (and its sub-tables).
TEST_F(ReadCase, UnknownKeyListsTheKeysOfTheSectionTable) {
  const std::string text =
      sf_test::replaced(sf_test::kMinimal, "thickness = 0.81", "thickness = 0.81\nthicknes = 1.0");
  std::string keys;
  for (const std::string_view key : sf::field_keys(sf::blank_fields())) {
    keys += (keys.empty() ? "" : ", ") + std::string(key);
  }
  expect_error(text, 4, {"blank.thicknes", "unknown key", keys});
  EXPECT_NE(keys.find("curvature_elements"), std::string::npos);  // a mesh source key
}

// A key of the table given where its condition does not hold is refused with the table's reason.
TEST_F(ReadCase, KeyOutsideItsConditionGivesTheTablesReason) {
  const std::string text =
      sf_test::replaced(sf_test::kMinimal, "thickness = 0.81", "thickness = 0.81\nhourglass = 0.1");
  expect_error(text, 4, {"blank.hourglass", "applies to formulation = \"belytschko_tsay\" only"});
}

}  // namespace
