// R_{N,E} (002 Sec. 9.2): hand-derived normal forms, and Lemma 3 as a
// property on random valid maps.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>

#include "checkers/map_validity.hpp"
#include "core/conjugate_words.hpp"
#include "core/limits.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"

using namespace dartcheck;

namespace {
std::vector<std::string> nf_strings(ConjugateRewriting& r, const char* w) {
  std::vector<std::string> out;
  for (const auto& nf : r.normal_forms(parse_conj_word(w, r.model()))) out.push_back(nf.str());
  return out;
}
// The model of 002 Examples 21-22: D = {1, 2}, N = ∅, E = {(1, 2)}.
Model both_oriented() {
  Model m;
  m.name = "D={1,2},N=∅,E={(1,2)}";
  m.dims = {1, 2};
  m.exchangeable = {{1, 2}};
  return m;
}
// D = O = {1,2,3}, every pair exchangeable: R_{N,E} is not confluent.
Model three_oriented() {
  Model m;
  m.name = "three oriented";
  m.dims = {1, 2, 3};
  m.exchangeable = {{1, 2}, {1, 3}, {2, 3}};
  return m;
}
}  // namespace

TEST(ConjWord, ParseAndPrint) {
  const Model o = Model::omap(2);
  EXPECT_EQ(parse_conj_word("~12", o).str(), "~12");
  EXPECT_EQ(parse_conj_word("1\u03042", o).str(), "~12") << "combining overbar after the digit";
  EXPECT_EQ(parse_conj_word("~2", o).str(), "2") << "2 is non-oriented in an O-map: 2̄ = 2";
  EXPECT_TRUE(parse_conj_word("ε", o).empty());
  EXPECT_THROW(parse_conj_word("13", o), ValueError) << "3 is not a dimension of a 2-O-map";
  EXPECT_THROW(parse_conj_word("1~", o), ValueError);
  EXPECT_THROW(parse_conj_word("1x", o), ValueError);
}

TEST(ConjugateRewriting, Conjugate) {
  ConjugateRewriting r(Model::omap(3));
  // conj(w1..wn) = conj(wn)..conj(w1); only the oriented 1 carries a bar.
  EXPECT_EQ(r.conjugate(parse_conj_word("12~13", r.model())).str(), "312~1");
}

// D = N ∪ O with O = {1,2,3} and every pair exchangeable: "321" rewrites
// at 32 into 2̄3̄1, where 3̄1 mixes a conjugated and a plain oriented letter
// and is stuck; at 21 into 31̄2̄, stuck at 31̄ likewise. Two normal forms.
TEST(ConjugateRewriting, NotConfluentAllNormalForms) {
  const Model m = three_oriented();
  ConjugateRewriting r(m);
  EXPECT_EQ(nf_strings(r, "321"), (std::vector<std::string>{"~2~31", "3~1~2"}));
  EXPECT_TRUE(r.congruent(parse_conj_word("3~1~2", m), parse_conj_word("~2~31", m))) << "congruent although neither rewrites to the other";
}

// 2-G-map: N = {0,1,2}, E = {(0,2)}.
TEST(ConjugateRewriting, GmapNormalForms) {
  ConjugateRewriting r(Model::gmap(2));
  EXPECT_EQ(nf_strings(r, "200"), (std::vector<std::string>{"2"})) << "020 rewrites on to 002, then 2";
  EXPECT_EQ(nf_strings(r, "0121"), (std::vector<std::string>{"0121"})) << "no exchangeable neighbours";
  EXPECT_EQ(nf_strings(r, "2101"), (std::vector<std::string>{"2101"}));
  EXPECT_EQ(nf_strings(r, "12021"), (std::vector<std::string>{"101"})) << "202 -> 022 -> 0";
  EXPECT_FALSE(r.congruent(parse_conj_word("01", r.model()), parse_conj_word("10", r.model()))) << "0 and 1 are not exchangeable";
}

// Example 23: the W-label of the 0202-cycle of a in the quad subdivision is
// ε2ε2 = 22 ->* ε.
TEST(ConjugateRewriting, Example23QuadCycleReducesToEmpty) {
  ConjugateRewriting r(Model::gmap(2));
  EXPECT_TRUE(r.reduces_to_empty(parse_conj_word("22", r.model())));
  EXPECT_TRUE(r.reduces_to_empty(parse_conj_word("0202", r.model())));
  EXPECT_FALSE(r.reduces_to_empty(parse_conj_word("0101", r.model()))) << "(0,1) is not in E";
}

// Examples 21-22 with N = ∅: 1 1̄ 1 ->* 1, and a 2121-cycle label reduces
// to ε: 21 -> 1̄2̄, then 2̄2 and 1̄1 cancel.
TEST(ConjugateRewriting, Examples21And22OrientedDimensions) {
  ConjugateRewriting r(both_oriented());
  EXPECT_EQ(nf_strings(r, "1~11"), (std::vector<std::string>{"1"}));
  EXPECT_TRUE(r.reduces_to_empty(parse_conj_word("2121", r.model())));
  EXPECT_TRUE(r.reduces_to_empty(parse_conj_word("~2~1~2~1", r.model())));
  EXPECT_FALSE(r.reduces_to_empty(parse_conj_word("2~12~1", r.model()))) << "an oriented letter does not swap with a conjugated one";
  EXPECT_FALSE(r.reduces_to_empty(parse_conj_word("11", r.model()))) << "1 is oriented: 11 is no back-and-forth";
}

namespace {
// A random word over the conjugate alphabet of `model`.
rc::Gen<ConjWord> gen_word(const Model& model, int max_len) {
  return rc::gen::map(rc::gen::container<std::vector<std::pair<int, bool>>>(
                          rc::gen::pair(rc::gen::inRange<int>(0, static_cast<int>(model.dims.size())), rc::gen::arbitrary<bool>())),
                      [model, max_len](const std::vector<std::pair<int, bool>>& letters) {
                        ConjWord w;
                        for (std::size_t k = 0; k < letters.size() && k < static_cast<std::size_t>(max_len); ++k)
                          w.push(model.dims[static_cast<std::size_t>(letters[k].first)], letters[k].second);
                        return ConjugateRewriting(model).normalize(w);
                      });
}

Model pick_model(int k) {
  static const Model models[] = {Model::gmap(1), Model::gmap(2), Model::gmap(3), Model::omap(2), Model::omap(3)};
  return models[k % 5];
}
}  // namespace

// Lemma 3: w ->* w' implies that on every combinatorial graph satisfying
// O(N) and C(E) the w-path and the w'-path from a node end at the same node.
// Random valid G-maps and O-maps; w' is reached by a random rewriting
// sequence; every dart of the map is a start node.
RC_GTEST_PROP(Lemma3, RewritingPreservesPathEndpoints, ()) {
  const Model model = pick_model(*rc::gen::inRange(0, 5));
  const Map map = build_random_map(model, *gen_map_recipe(1, 8));
  RC_PRE(check_map(map).valid());
  ConjugateRewriting r(model);
  ConjWord w = *gen_word(model, 12);
  const ConjWord start = w;
  for (int k = *rc::gen::inRange(0, 20); k > 0; --k) {
    auto steps = r.steps(w);
    if (steps.empty()) break;
    w = steps[*rc::gen::inRange<std::size_t>(0, steps.size())].result;
  }
  for (Dart d = 0; d < map.size(); ++d) RC_ASSERT(follow(map, d, start) == follow(map, d, w));
  // Corollary 2: a word that reduces to ε labels cycles only.
  if (r.reduces_to_empty(start))
    for (Dart d = 0; d < map.size(); ++d) RC_ASSERT(follow(map, d, start) == d);
}

// The congruence decision is complete on words related by the symmetric
// closure: w' is built from w by random steps in both directions (rewrite,
// or insert x x̄ / undo a swap anywhere); congruent(w, w') must hold. It is
// also sound: congruent words end at the same dart on random maps.
RC_GTEST_PROP(ConjugateRewriting, CongruenceDecidesTheSymmetricClosure, ()) {
  const Model model = pick_model(*rc::gen::inRange(0, 5));
  ConjugateRewriting r(model);
  const ConjWord w = *gen_word(model, 8);
  ConjWord v = w;
  for (int k = *rc::gen::inRange(0, 12); k > 0; --k) {
    const int kind = *rc::gen::inRange(0, 3);
    if (kind == 0 && v.size() >= 2) {
      // Backward swap: u -> v by swapping y x at k into x̄ ȳ = v[k] v[k+1].
      const std::size_t at = *rc::gen::inRange<std::size_t>(0, v.size() - 1);
      const ConjWord a = ConjWord::from_code(v.code().substr(at, 1)), b = ConjWord::from_code(v.code().substr(at + 1, 1));
      const ConjWord u = ConjWord::from_code(v.code().substr(0, at)) + r.conjugate(b) + r.conjugate(a) + ConjWord::from_code(v.code().substr(at + 2));
      for (const auto& s : r.steps(u))
        if (s.kind == ConjugateRewriting::Step::swap && s.position == at && s.result == v) {
          v = u;
          break;
        }
    } else if (kind == 1) {
      // Backward cancellation: insert x x̄ at a position.
      const std::size_t at = *rc::gen::inRange<std::size_t>(0, v.size() + 1);
      ConjWord x;
      x.push(model.dims[*rc::gen::inRange<std::size_t>(0, model.dims.size())], *rc::gen::arbitrary<bool>());
      x = r.normalize(x);
      const ConjWord prefix = ConjWord::from_code(v.code().substr(0, at));
      const ConjWord suffix = ConjWord::from_code(v.code().substr(at));
      v = prefix + x + r.conjugate(x) + suffix;
    } else {
      auto steps = r.steps(v);
      if (!steps.empty()) v = steps[*rc::gen::inRange<std::size_t>(0, steps.size())].result;
    }
    if (v.size() > 18) break;
  }
  RC_ASSERT(r.congruent(w, v));
  RC_ASSERT(r.congruent(v, w));
  const Map map = build_random_map(model, *gen_map_recipe(1, 6));
  for (Dart d = 0; d < map.size(); ++d) RC_ASSERT(follow(map, d, w) == follow(map, d, v));
}

namespace {
// The irreducible words reachable from w by the one-step rewritings of
// steps() (the definition of a normal form, by brute force).
std::set<std::string> reachable_normal_forms(const ConjugateRewriting& r, const ConjWord& w) {
  std::set<std::string> seen{w.code()}, forms;
  std::vector<ConjWord> todo{w};
  while (!todo.empty()) {
    const ConjWord v = todo.back();
    todo.pop_back();
    const auto steps = r.steps(v);
    if (steps.empty()) forms.insert(v.str());
    for (const auto& s : steps)
      if (seen.insert(s.result.code()).second) todo.push_back(s.result);
  }
  return forms;
}

std::set<std::string> as_set(const std::vector<ConjWord>& words) {
  std::set<std::string> out;
  for (const auto& w : words) out.insert(w.str());
  return out;
}
}  // namespace

// Theorem (core/conjugate_words.hpp): without two exchangeable oriented
// dimensions R_{N,E} is confluent, so a word has one normal form, which
// the insertion computes. Checked against every rewriting sequence (brute
// force over steps()) on the G-map and O-map models, closed and open.
RC_GTEST_PROP(ConjugateRewriting, ConfluentModelsHaveTheOneNormalFormOfEverySequence, ()) {
  static const Model models[] = {Model::gmap(1), Model::gmap(2), Model::gmap(3),        Model::omap(2),
                                 Model::omap(3), Model::omap(4), Model::closed_gmap(3), Model::open_omap(3)};
  const Model& model = models[*rc::gen::inRange(0, 8)];
  ConjugateRewriting r(model);
  const ConjWord w = *gen_word(model, 10);
  const auto oracle = reachable_normal_forms(r, w);
  RC_ASSERT(oracle.size() == 1U);
  RC_ASSERT(as_set(r.normal_forms(w)) == oracle);
  RC_ASSERT(r.reduces_to_empty(w) == (*oracle.begin() == "ε"));
}

// On the models where it is not confluent, every normal form, as before.
RC_GTEST_PROP(ConjugateRewriting, NonConfluentModelsGiveEveryNormalForm, ()) {
  const Model model = *rc::gen::arbitrary<bool>() ? three_oriented() : both_oriented();
  ConjugateRewriting r(model);
  const ConjWord w = *gen_word(model, 7);
  const auto oracle = reachable_normal_forms(r, w);
  RC_ASSERT(as_set(r.normal_forms(w)) == oracle);
  // ε is irreducible: w ->* ε iff ε is one of the normal forms.
  RC_ASSERT(r.reduces_to_empty(w) == (oracle.count("ε") > 0));
}

// The words of issue 38: (13)^k on a 3-O-map took 181 s and 2.8 GB at 28
// letters. By hand: 31 -> 1̄3 (3 is non-oriented), so 1 3 1 3 -> 1 1̄ 3 3
// -> ε and (13)^(2k) reduces to ε; (13)^(2k+1) to 13.
TEST(ConjugateRewriting, LongWordsOfConfluentModelsArePolynomial) {
  ConjugateRewriting r(Model::omap(3));
  std::string even, odd = "13";
  for (int k = 0; k < 2000; ++k) even += "13";
  odd += even;
  EXPECT_EQ(nf_strings(r, even.c_str()), (std::vector<std::string>{"ε"}));
  EXPECT_EQ(nf_strings(r, odd.c_str()), (std::vector<std::string>{"13"}));
  EXPECT_TRUE(r.reduces_to_empty(parse_conj_word(even, r.model())));
}

// The general search is bounded: a long word of a non-confluent model
// stops at limits().rewrite_words with RewriteLimit, naming the option.
TEST(ConjugateRewriting, NonConfluentSearchStopsAtItsLimit) {
  const Model m = three_oriented();
  ConjugateRewriting r(m);
  const std::size_t saved = limits().rewrite_words;
  limits().rewrite_words = 1000;
  try {
    (void)r.normal_forms(parse_conj_word("321321321321321321321321", m));
    ADD_FAILURE() << "no limit";
  } catch (const RewriteLimit& e) {
    EXPECT_NE(std::string(e.what()).find("--limit-rewrite-words"), std::string::npos) << e.what();
  }
  limits().rewrite_words = saved;
}
