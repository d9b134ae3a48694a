#include "contact/contact_search.hpp"

#include <fmt/core.h>

#include <array>
#include <string>

#include "contact/cached_search.hpp"
#include "contact/modified_search.hpp"
#include "contact/standard_search.hpp"
#include "core/errors.hpp"

namespace sf {

namespace {

struct NamedSearch {
  ContactSearchKind kind;
  std::string_view name;
};

constexpr std::array<NamedSearch, 5> kSearchNames{{
    {ContactSearchKind::standard, "standard"},
    {ContactSearchKind::standard_brute_force, "standard_brute_force"},
    {ContactSearchKind::modified, "modified"},
    {ContactSearchKind::modified_brute_force, "modified_brute_force"},
    {ContactSearchKind::cached, "cached"},
}};

}  // namespace

std::string_view contact_search_name(ContactSearchKind kind) {
  for (const NamedSearch& s : kSearchNames) {
    if (s.kind == kind) {
      return s.name;
    }
  }
  return "unknown";
}

ContactSearchKind parse_contact_search(std::string_view name, std::string_view where) {
  std::string accepted;
  for (const NamedSearch& s : kSearchNames) {
    if (s.name == name) {
      return s.kind;
    }
    accepted += fmt::format("{}{}", accepted.empty() ? "" : ", ", s.name);
  }
  throw InputError(
      fmt::format("{}: unknown contact search '{}' (accepted: {})", where, name, accepted));
}

std::unique_ptr<ContactSearch> make_contact_search(std::string_view name,
                                                   const TriangleSurface& surface,
                                                   const SearchOptions& options) {
  return make_contact_search(parse_contact_search(name, fmt::format("tool '{}'", surface.name())),
                             surface, options);
}

std::unique_ptr<ContactSearch> make_contact_search(ContactSearchKind kind,
                                                   const TriangleSurface& surface,
                                                   const SearchOptions& options) {
  switch (kind) {
    case ContactSearchKind::modified:
      return std::make_unique<ModifiedSearch>(surface);
    case ContactSearchKind::modified_brute_force:
      return std::make_unique<ModifiedBruteForceSearch>(surface);
    case ContactSearchKind::standard:
      return std::make_unique<StandardSearch>(surface);
    case ContactSearchKind::standard_brute_force:
      return std::make_unique<StandardBruteForceSearch>(surface);
    case ContactSearchKind::cached:
      return std::make_unique<CachedSearch>(surface, options.cached_margin,
                                            options.cached_capacity);
  }
  throw InputError(fmt::format("tool '{}': unknown contact search", surface.name()));
}

}  // namespace sf
