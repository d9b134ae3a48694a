#include "contact/contact_search.hpp"

#include <fmt/core.h>

#include <string>

#include "contact/cached_search.hpp"
#include "contact/modified_search.hpp"
#include "contact/standard_search.hpp"
#include "core/errors.hpp"

namespace sf {

std::string_view contact_search_name(ContactSearchKind kind) {
  return choice_name<ContactSearchKind>(kContactSearchNames, kind);
}

ContactSearchKind parse_contact_search(std::string_view name, std::string_view where) {
  if (const auto kind = find_choice<ContactSearchKind>(kContactSearchNames, name)) {
    return *kind;
  }
  throw InputError(fmt::format("{}: unknown contact search '{}' (accepted: {})", where, name,
                               choice_list<ContactSearchKind>(kContactSearchNames, "")));
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
