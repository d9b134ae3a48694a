#include "contact/contact_search.hpp"

#include <fmt/core.h>

#include "contact/cached_search.hpp"
#include "contact/modified_search.hpp"
#include "contact/standard_search.hpp"
#include "core/errors.hpp"

namespace sf {

std::unique_ptr<ContactSearch> make_contact_search(std::string_view name,
                                                   const TriangleSurface& surface,
                                                   const SearchOptions& options) {
  if (name == "modified") {
    return std::make_unique<ModifiedSearch>(surface);
  }
  if (name == "modified_brute_force") {
    return std::make_unique<ModifiedBruteForceSearch>(surface);
  }
  if (name == "standard") {
    return std::make_unique<StandardSearch>(surface);
  }
  if (name == "standard_brute_force") {
    return std::make_unique<StandardBruteForceSearch>(surface);
  }
  if (name == "cached") {
    return std::make_unique<CachedSearch>(surface, options.cached_margin, options.cached_capacity);
  }
  throw InputError(
      fmt::format("tool '{}': unknown contact search '{}' (accepted: standard, "
                  "standard_brute_force, modified, modified_brute_force, cached)",
                  surface.name(), name));
}

}  // namespace sf
