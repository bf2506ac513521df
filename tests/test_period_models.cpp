// The registry of experiment kinds (models/registry.hpp, docs/core.md): every
// registered period model declares each piece of the interface, and what it
// declares is what it does. A kind added without a piece fails here (or does
// not compile: registry.hpp's static_assert).
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "catalogue.hpp"
#include "pendulum/models/registry.hpp"
#include "pendulum/json/scene_json.hpp"

using namespace pendulum;

TEST_CASE("Every registered kind names its parameters, units, defaults and settings, each once", "[models]") {
  std::set<std::string> names;
  std::set<int> settings;
  int kinds = 0;
  for_each_period_model([&](auto model) {
    using M = decltype(model);
    INFO(M::kName);
    ++kinds;
    CHECK(names.insert(M::kName).second);
    CHECK(std::string(M::kParameterInfo[0].name) == "g");
    std::set<std::string> parameters;
    for (const ParameterInfo& p : M::kParameterInfo) {
      CHECK(parameters.insert(p.name).second);
      CHECK(std::string(p.unit).size() > 0);
      CHECK(std::string(p.description).size() > 0);
    }
    for (double x : M::kDefaults) CHECK(std::isfinite(x));
    // One kind per setting: the reader knows the kind from an observation's key.
    for (Setting s : M::kSettings) {
      CHECK(settings.insert(static_cast<int>(s)).second);
      CHECK(kind_of_setting(s) == kind_of<M>());
    }
  });
  CHECK(kinds == static_cast<int>(std::tuple_size_v<PeriodModels>));
  // Every setting belongs to a kind.
  for (const SettingInfo& s : kSettingInfo) {
    INFO(s.key);
    CHECK(settings.count(static_cast<int>(s.setting)) == 1);
  }
}

// On every valid scene (tests/valid_scenes.json and Nelson & Olsson's), in
// its kind: a registered kind without one fails.
TEST_CASE("Every registered kind's rows are what its kCorrectionUse declares", "[models][corrections]") {
  std::set<int> kinds;
  std::set<std::pair<int, int>> replaced_computed;  // (kind, row): a replaced row computed in some scene
  const SceneFiles files{std::string(PENDULUM_TESTS_DIR), true};
  for (const std::string& text : test::valid_scene_texts()) {
    const ParsedScene scene = parse_scene(text, files);
    visit_period_model(scene.model, [&](auto model) {
      using M = decltype(model);
      INFO(scene.title);
      kinds.insert(static_cast<int>(kind_of<M>().index));
      const Apparatus<double>& app = scene.apparatus;
      const Observation<double>& o = scene.observations.front();
      std::array<double, M::kParameters> p = M::kDefaults;
      const AmplitudeChoice amplitude{AmplitudeMethod::agm, 0, 0.0};
      const PeriodPrediction<double> predicted = M::predict(p.data(), o, app, amplitude);
      const Terms<double> plain = correction_terms(app, M::swing_at(p.data(), M::swing(o), app), amplitude);
      for (int i = 0; i < kCorrectionCount; ++i) {
        INFO(M::kName << " " << kCorrections[i].id);
        const Term<double>& row = predicted.terms[i];
        switch (M::kCorrectionUse[i]) {
          case CorrectionUse::applies:
            CHECK(row.ratio.has_value() == plain[i].ratio.has_value());
            CHECK(std::string(row.method) == plain[i].method);
            break;
          case CorrectionUse::replaced:  // by the model's formula, or skipped for a part the scene lacks
            if (row.ratio) {
              replaced_computed.insert({static_cast<int>(kind_of<M>().index), i});
              CHECK(std::string(row.method) != plain[i].method);
            } else {
              CHECK(std::string(row.skip_reason).size() > 0);
            }
            break;
          case CorrectionUse::not_applicable:
            CHECK(!row.ratio);
            CHECK(std::string(row.skip_reason).size() > 0);
            break;
        }
      }
      // The composition without rows is the rows' composition, to the rounding
      // of a sum in another order (a few ulp of the largest row).
      double scale = 0.0;
      for (const Term<double>& row : predicted.terms) scale += row.ratio ? std::abs(*row.ratio) : 0.0;
      CHECK(M::composition(app, M::swing_at(p.data(), M::swing(o), app), amplitude).total ==
            Approx(predicted.composition.total).epsilon(1e-15).margin(1e-15 * scale));
    });
  }
  CHECK(kinds.size() == std::tuple_size_v<PeriodModels>);
  for_each_period_model([&](auto model) {
    using M = decltype(model);
    for (int i = 0; i < kCorrectionCount; ++i) {
      INFO(M::kName << " " << kCorrections[i].id);
      if (M::kCorrectionUse[i] == CorrectionUse::replaced) CHECK(replaced_computed.count({static_cast<int>(kind_of<M>().index), i}));
    }
  });
}

namespace {
// A kind with one piece of the interface hidden (a derived declaration of
// the same name and another signature hides the base's).
struct WithoutStart : SimplePendulum {
  static void start() = delete;
};
struct WithoutReport : SimplePendulum {
  static void report() = delete;
};
// Results of another type than its writers take.
struct ResultsOfAnotherType : PhysicalPendulum {
  using Results = void;
};
struct WithoutPutFitResults : SimplePendulum {
  static void put_fit_results() = delete;
};
struct WithoutPutObservationResults : PhysicalPendulum {
  static void put_observation_results() = delete;
};
struct WithoutFitResultsLines : PhysicalPendulum {
  static void fit_results_lines() = delete;
};
struct WithoutObservationResultsLines : SimplePendulum {
  static void observation_results_lines() = delete;
};
struct WithoutPredict : SimplePendulum {
  static void predict() = delete;
};
struct WithoutOwnCorrections : SimplePendulum {
  static void own_corrections() = delete;
};
struct WithoutSolveG : SimplePendulum {
  static void solve_g() = delete;
};
struct WithoutReadKeys : PhysicalPendulum {
  static void read_keys() = delete;
};
struct WithoutUnknownsOfObservationsAlone : PhysicalPendulum {
  static void unknowns_of_observations_alone() = delete;
};
struct WithoutExpectation : SimplePendulum {
  static void expectation() = delete;
};
struct WithoutCheckRows : SimplePendulum {
  static void check_rows() = delete;
};
struct WithoutSkippedPartWarnings : SimplePendulum {
  static void skipped_part_warnings() = delete;
};
// The verdict's words in another type than SuspectCauses.
struct WithoutSuspectCauses : PhysicalPendulum {
  static constexpr const char* kSuspectCauses = "a pivot position misread";
};
// The plausibility checks' expectation in another type than Expectation.
struct ExpectingAPeriodAlone : SimplePendulum {
  static std::optional<double> expectation(const ParsedScene&, const Observation<double>&) { return 1.0; }
};
}  // namespace

TEST_CASE("A kind that lacks a piece of the interface is not a period model", "[models]") {
  STATIC_REQUIRE(is_period_model<SimplePendulum>());
  STATIC_REQUIRE(is_period_model<PhysicalPendulum>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutStart>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutReport>());
  STATIC_REQUIRE_FALSE(is_period_model<ResultsOfAnotherType>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutPutFitResults>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutPutObservationResults>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutFitResultsLines>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutObservationResultsLines>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutPredict>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutOwnCorrections>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutSolveG>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutReadKeys>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutUnknownsOfObservationsAlone>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutExpectation>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutCheckRows>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutSkippedPartWarnings>());
  STATIC_REQUIRE_FALSE(is_period_model<WithoutSuspectCauses>());
  STATIC_REQUIRE_FALSE(is_period_model<ExpectingAPeriodAlone>());
}
