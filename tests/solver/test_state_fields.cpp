// The one description of the run state (solver/state_fields.hpp, issue 32 item 1): every member of
// the state is either described or named as left out, the roles agree with each other, and the
// keys and units are what the files need.
#include <gtest/gtest.h>

#include <cstddef>
#include <set>
#include <string>
#include <utility>

#include "solver/state_fields.hpp"

namespace sf {
namespace {

// Converts to any member type: T{AnyMember, ...} compiles for as many arguments as the
// aggregate T has members, and no more (an expression that converts is never brace-elided).
struct AnyMember {
  template <class T>
  operator T() const;  // NOLINT(google-explicit-constructor): only in unevaluated contexts
};

template <class T, std::size_t... I>
constexpr bool initializable_with(std::index_sequence<I...>) {
  return requires {
    T{(static_cast<void>(I), AnyMember{})...};
  };
}

template <class T, std::size_t N = 0>
constexpr std::size_t member_count() {
  if constexpr (initializable_with<T>(std::make_index_sequence<N + 1>{})) {
    return member_count<T, N + 1>();
  } else {
    return N;
  }
}

// The members of the state's structs, as described in state_fields.hpp. When one of these fails,
// a member was added or removed: describe it (a StateField and a line of visit_state_fields) or
// name it in kStateLeftOut with the reason, then set the count here.
TEST(StateFields, EveryMemberIsDescribedOrLeftOut) {
  // 37 visited (11 run numbers, 19 node arrays; scaling, shell, energies, tools, contacts,
  // drawbeads, the operation), 9 left out: mass_before, inertia_before, element_pass, domain,
  // contact_sums, pressure_corners, contact_off, released_loads, times.
  EXPECT_EQ(member_count<SolutionState>(), 46u);
  EXPECT_EQ(member_count<OperationState>(), 5u);  // all visited
  // 12 arrays visited; n_elements and n_points are the model's sizes.
  EXPECT_EQ(member_count<ShellState>(), 14u);
  // added_mass, scaled_elements, density_factor, element_dt visited; target_dt, safety,
  // element_mass, inertia_factor the model's; scaled_dt, corner_mass scratch.
  EXPECT_EQ(member_count<MassScaling>(), 10u);
  EXPECT_EQ(member_count<Energies>(), 13u);         // all visited
  EXPECT_EQ(member_count<ToolState>(), 16u);        // all visited
  EXPECT_EQ(member_count<ToolMotionOrigin>(), 6u);  // all visited
  // stick_force, normal_force, sliding_distance and distance_bounds (anchors, slacks) visited;
  // node_count, search_cache, search, shares, ghost_shares rebuilt or scratch; the 4 flags of
  // warned_beyond_table (an array counts one a element) messages.
  EXPECT_EQ(member_count<ContactState>(), 13u);
  // restraint visited; shares, ghost_shares scratch.
  EXPECT_EQ(member_count<DrawbeadState>(), 3u);
}

struct Entry {
  StateField field;
  std::string key;
};

class Recorder {
 public:
  template <class T>
  void operator()(const StateField& field, const std::string& key, const T&) {
    entries.push_back({field, key});
  }
  std::vector<Entry> entries;
};

std::vector<Entry> entries_of_a_state_with_a_tool_and_a_contact() {
  SolutionState s;
  s.tools.resize(1);
  s.contacts.resize(1);
  Recorder recorder;
  visit_state_fields(recorder, s);
  return recorder.entries;
}

TEST(StateFields, KeysAreUniqueAndEveryFieldHasAUnitAndAMeaning) {
  std::set<std::string> keys;
  for (const Entry& e : entries_of_a_state_with_a_tool_and_a_contact()) {
    EXPECT_TRUE(keys.insert(e.key).second) << "key " << e.key << " twice";
    EXPECT_FALSE(e.field.unit.empty()) << e.key;
    EXPECT_FALSE(e.field.meaning.empty()) << e.key;
    EXPECT_NE(e.key.find(e.field.name), std::string::npos)
        << "key " << e.key << " does not hold its field's name " << e.field.name;
  }
  // 11 + 5 of the operation + 19 node + 4 mass scaling + 12 shell + 12 energies + a tool's (6
  // scalars, 4 x 3 vectors, 2 x 9 rotations, the angle, 2 x 3 moments, the origin's 3 + 3 + 9 +
  // 1) + 8 of a pair (its stick and normal forces, sliding distances, distance bounds' anchors and
  // slacks, front bounds' anchors, sides and gaps)
  EXPECT_EQ(keys.size(), 11u + 5u + 19u + 4u + 12u + 12u + 59u + 8u);
}

TEST(StateFields, RolesAgree) {
  for (const Entry& e : entries_of_a_state_with_a_tool_and_a_contact()) {
    const StateField& f = e.field;
    // What the next operation starts from, a restart needs too; what output shows is handed on.
    if (f.has(field_role::formed_part) || f.has(field_role::output)) {
      EXPECT_TRUE(f.has(field_role::checkpoint)) << e.key;
    }
    if (f.has(field_role::output)) {
      EXPECT_TRUE(f.has(field_role::formed_part)) << e.key;
      // Only arrays are gathered; run numbers are the same on every process.
      EXPECT_TRUE(f.place == FieldPlace::node || f.place == FieldPlace::element ||
                  f.place == FieldPlace::point || f.place == FieldPlace::contact)
          << e.key;
    }
    // Of a contact pair's history the friction's stick forces and the results (normal forces,
    // sliding distances) are handed on; the distance bounds are a shortcut of the search, which
    // starts afresh, and a drawbead's springs start afresh in the next case.
    if (f.place == FieldPlace::contact) {
      EXPECT_EQ(f.has(field_role::formed_part),
                f.name == "stick_force" || f.name == "normal_force" || f.name == "sliding_distance")
          << e.key;
    }
    // The mesh's fields say how they follow a new mesh; the rest are not of the mesh.
    const bool of_the_mesh = f.place == FieldPlace::node || f.place == FieldPlace::element ||
                             f.place == FieldPlace::point || f.place == FieldPlace::contact;
    EXPECT_EQ(of_the_mesh, f.mapping != FieldMapping::none) << e.key;
  }
}

}  // namespace
}  // namespace sf
