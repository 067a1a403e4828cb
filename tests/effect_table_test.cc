// The effects' parameter tables (Spec(), problems/effects.h) are the one
// source of the scene catalogue: the defaults are the members' initializers,
// a scene's values land in the members they name, and the README's effect
// table is the generated one.
#define BOOST_TEST_MODULE effect_table
#include <boost/test/unit_test.hpp>
#include <string>

#include "scene/catalogue.h"
#include "scene/scene.h"
#include "tests/readme_quote.h"

BOOST_AUTO_TEST_CASE(Readme_HasTheGeneratedEffectTable) {
  const std::string readme = readme_quote::Slurp(VIVP_SOURCE_DIR "/README.md");
  const std::string table = vivp::scene::EffectTableMarkdown();
  BOOST_TEST(readme.find(table) != std::string::npos,
             "README.md's effect table is out of date; run "
             "scripts/update_readme_effects.sh");
}

BOOST_AUTO_TEST_CASE(EveryBuiltInEffect_BuildsFromItsDefaults) {
  // Values as the reader fills them: each parameter's default, a vector
  // default repeated over the coordinates.
  const int dof = 2;
  for (const auto& type : vivp::scene::BuiltInEffects()) {
    vivp::scene::ParameterValues values;
    for (const auto& p : type.parameters) {
      if (p.fallback.empty()) continue;  // optional: absent
      values[p.name] = p.kind == vivp::scene::ParameterKind::kVector
                           ? std::vector<double>(dof, p.fallback[0])
                           : p.fallback;
    }
    const auto effect = vivp::scene::MakeEffect(type, values);
    // The built effect is the alternative of that name, and its Lagrangian
    // equals the default-constructed struct's at a sample point.
    std::visit(
        [&](const auto& e) {
          using E = std::decay_t<decltype(e)>;
          BOOST_TEST(E::Spec().name == type.name);
          if constexpr (vivp::problems::HasLagrangian<E>) {
            const double x[dof] = {0.3, -0.7}, v[dof] = {0.5, 0.2};
            BOOST_TEST(e.template Lagrangian<dof>(x, v) ==
                           E{}.template Lagrangian<dof>(x, v),
                       type.name);
          }
        },
        effect);
  }
}

BOOST_AUTO_TEST_CASE(SceneValues_LandInTheMembersTheyName) {
  const auto* chain = vivp::scene::FindEffectType("chain");
  BOOST_TEST_REQUIRE(chain != nullptr);
  const auto effect = vivp::scene::MakeEffect(
      *chain, {{"k", {2.5}}, {"beta", {0.75}}, {"fixed_ends", {0.0}}});
  const auto& c = std::get<vivp::problems::effects::Chain>(effect);
  BOOST_TEST(c.k == 2.5);
  BOOST_TEST(c.beta == 0.75);
  BOOST_TEST(!c.fixed_ends);
}
