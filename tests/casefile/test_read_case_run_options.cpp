// run's --stroke, --end-time and --search (CaseOptions) are applied to the case file's keys before
// the case is read: the reader checks them like the file's own keys, an error names the option,
// and the resolved case holds them.
#include <gtest/gtest.h>

#include "casefile/case_config.hpp"
#include "read_case_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using sf_test::kFull;
using sf_test::kMinimal;
using sf_test::ReadCase;

TEST_F(ReadCase, StrokeOptionReplacesTheEndTime) {
  const sf::CaseConfig c = sf::read_case(write_case(kFull), sf::CaseOptions{.stroke = 2.5});
  EXPECT_EQ(c.control.stroke, 2.5);
  EXPECT_EQ(c.control.end_time, 0.0);
  const std::string resolved = sf::format_resolved_case(c);
  sf_test::expect_contains(resolved, "\nstroke = 2.5");
  const sf::CaseConfig again = sf::read_case(write_case(resolved, "resolved/case.toml"));
  EXPECT_EQ(again.control.stroke, 2.5);
}

TEST_F(ReadCase, EndTimeOptionReplacesTheStroke) {
  const sf::CaseConfig c = sf::read_case(write_case(kFull), sf::CaseOptions{.end_time = 1e-3});
  EXPECT_EQ(c.control.end_time, 1e-3);
  EXPECT_EQ(c.control.stroke, 0.0);
}

// Checked like the file's keys: a stroke needs a moving tool (the minimal case has none), and the
// message names the option instead of a line of the case file.
TEST_F(ReadCase, StrokeOptionWithoutAMovingToolIsRefusedNamingTheOption) {
  const fs::path file = write_case(kMinimal);
  try {
    sf::read_case(file, sf::CaseOptions{.stroke = 5.0});
    FAIL() << "a stroke without a moving tool must be refused";
  } catch (const sf::InputError& e) {
    sf_test::expect_contains(e.what(), "command line (--stroke 5.0)");
    sf_test::expect_contains(e.what(), "needs a moving tool");
  }
}

TEST_F(ReadCase, BadRunOptionsAreRefused) {
  const fs::path file = write_case(kFull);
  const auto message = [&](const sf::CaseOptions& options) -> std::string {
    try {
      sf::read_case(file, options);
    } catch (const sf::InputError& e) {
      return e.what();
    }
    return "no error";
  };
  sf_test::expect_contains(message({.stroke = 1.0, .end_time = 1.0}), "not both");
  sf_test::expect_contains(message({.stroke = -5.0}), "--stroke -5: expected a finite value > 0");
  sf_test::expect_contains(message({.end_time = 0.0}), "--end-time 0: expected a finite value > 0");
  const fs::path minimal = write_case(kMinimal, "minimal.toml");
  try {
    sf::read_case(minimal, sf::CaseOptions{.search = sf::ContactSearchKind::standard});
    ADD_FAILURE() << "--search without a contact must be refused";
  } catch (const sf::InputError& e) {
    sf_test::expect_contains(e.what(), "--search needs a [[contact]]");
  }
}

// Every contact takes the search; a cached search's margin is dropped for another search.
TEST_F(ReadCase, SearchOptionSetsEveryContactsSearch) {
  const std::string cached =
      sf_test::replaced(kFull, "search = \"modified\"", "search = \"cached\"\nsearch_margin = 0.2");
  const fs::path file = write_case(cached);
  EXPECT_EQ(sf::read_case(file).contacts[0].search_margin, 0.2);
  const sf::CaseConfig c =
      sf::read_case(file, sf::CaseOptions{.search = sf::ContactSearchKind::standard});
  ASSERT_EQ(c.contacts.size(), 2u);
  for (const sf::ContactConfig& contact : c.contacts) {
    EXPECT_EQ(contact.search, sf::ContactSearchKind::standard);
    EXPECT_EQ(contact.search_margin, 0.0);
  }
  const sf::CaseConfig kept =
      sf::read_case(file, sf::CaseOptions{.search = sf::ContactSearchKind::cached});
  EXPECT_EQ(kept.contacts[0].search_margin, 0.2);
  EXPECT_EQ(kept.contacts[1].search, sf::ContactSearchKind::cached);
}

}  // namespace
