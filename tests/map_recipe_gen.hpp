// RapidCheck's generator of map recipes (generators/random_maps.hpp), for
// the property tests only: the dartcheck binary does not link RapidCheck.
#pragma once

#include <rapidcheck.h>

#include "generators/random_maps.hpp"

namespace dartcheck {

/// Recipes with `min_faces`..`max_faces` faces and up to twice as many
/// sewings.
inline rc::Gen<MapRecipe> gen_map_recipe(int min_faces, int max_faces) {
  return rc::gen::mapcat(rc::gen::inRange(min_faces, max_faces + 1), [](int faces) {
    return rc::gen::build<MapRecipe>(
        rc::gen::set(&MapRecipe::face_sizes,
                     rc::gen::container<std::vector<std::uint8_t>>(static_cast<std::size_t>(faces), rc::gen::inRange<std::uint8_t>(1, 7))),
        rc::gen::set(&MapRecipe::sewings, rc::gen::container<std::vector<SewStep>>(
                                              static_cast<std::size_t>(2 * faces),
                                              rc::gen::build<SewStep>(rc::gen::set(&SewStep::dim, rc::gen::element<std::uint8_t>(2, 3)),
                                                                      rc::gen::set(&SewStep::a, rc::gen::inRange<std::uint32_t>(0, 1000)),
                                                                      rc::gen::set(&SewStep::b, rc::gen::inRange<std::uint32_t>(0, 1000)),
                                                                      rc::gen::set(&SewStep::twist, rc::gen::inRange<std::uint32_t>(0, 1000))))));
  });
}

}  // namespace dartcheck

namespace rc {
template <>
struct Arbitrary<dartcheck::LinkCorruption> {
  static Gen<dartcheck::LinkCorruption> arbitrary() {
    return gen::build<dartcheck::LinkCorruption>(gen::set(&dartcheck::LinkCorruption::dart), gen::set(&dartcheck::LinkCorruption::dim),
                                                 gen::set(&dartcheck::LinkCorruption::target), gen::set(&dartcheck::LinkCorruption::inverse),
                                                 gen::set(&dartcheck::LinkCorruption::resew));
  }
};
}  // namespace rc
