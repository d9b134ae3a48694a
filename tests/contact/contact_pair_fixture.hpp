#pragma once
// A penalty contact pair over one tool surface, and a friction law, for the contact tests.
#include "contact/contact_search.hpp"
#include "contact/contact_state.hpp"
#include "contact/coulomb_friction.hpp"
#include "contact/penalty_contact.hpp"

namespace sf::test {

/// A contact pair and its state.
struct Contact {
  ContactPair pair;
  ContactState state;
};

/// The modified search over `s` for n blank nodes, each of penalty stiffness k (N/mm), cutoff
/// 2 mm, with friction `law`. `s` must outlive the pair.
inline Contact make_pair(const TriangleSurface& s, int n, double k,
                         const FrictionParameters& law = {}) {
  Contact c;
  c.pair.surface = &s;
  c.pair.search = make_contact_search("modified", s);
  c.pair.stiffness = VectorX::Constant(n, k);
  c.pair.cutoff = 2.0;
  c.pair.friction = law;
  return c;
}

/// Coulomb friction: static and dynamic coefficients and the decay (s/mm) between them.
inline FrictionParameters make_law(double mu_s, double mu_d, double decay) {
  FrictionParameters law;
  law.static_coefficient = mu_s;
  law.dynamic_coefficient = mu_d;
  law.decay = decay;
  return law;
}

}  // namespace sf::test
