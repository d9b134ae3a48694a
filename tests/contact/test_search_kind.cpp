// The contact searches' one name table: every kind's name parses back to it, and an unknown name
// is an InputError that names where it came from and lists the accepted names.
#include <gtest/gtest.h>

#include <string>

#include "contact/contact_search.hpp"
#include "core/errors.hpp"

namespace sf {
namespace {

TEST(ContactSearchKind, EveryNameParsesBackToItsKind) {
  for (const ContactSearchKind kind :
       {ContactSearchKind::standard, ContactSearchKind::standard_brute_force,
        ContactSearchKind::modified, ContactSearchKind::modified_brute_force,
        ContactSearchKind::cached}) {
    EXPECT_EQ(parse_contact_search(contact_search_name(kind), "test"), kind);
  }
  EXPECT_EQ(contact_search_name(ContactSearchKind::cached), "cached");
}

TEST(ContactSearchKind, UnknownNameNamesTheEntryAndTheAcceptedOnes) {
  try {
    parse_contact_search("closest", "case.toml: contact with tool 'die'");
    FAIL() << "an unknown search must be refused";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("case.toml: contact with tool 'die'"), std::string::npos) << message;
    EXPECT_NE(message.find("'closest'"), std::string::npos) << message;
    EXPECT_NE(
        message.find("standard, standard_brute_force, modified, modified_brute_force, cached"),
        std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace sf
