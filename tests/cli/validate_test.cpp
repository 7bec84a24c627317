// CLI tier: `oceanglobe validate --json` keeps its shape (issue #18): per view, per band (near,
// mid, far, all) the three models' mean and max |row error|, and the same per lighting term.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "support/RunBinary.hpp"

namespace {
og::test::RunResult run(const std::string& args) { return og::test::runOceanglobe(args, "cli_validate"); }
}  // namespace

TEST(CliValidate, JsonHasEveryBandModelAndTerm) {
  const auto r = run("validate --view 20m_away --json --width 48 --height 27 --supersample 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["views"].size(), 1u);
  const auto& v = j["views"][0];
  EXPECT_EQ(v["name"], "20m_away");
  for (const char* band : {"near", "mid", "far", "all"}) {
    const auto& b = v["bands"][band];
    ASSERT_TRUE(b.is_object()) << band;
    EXPECT_GT(b["rows"].get<int>(), 0) << band;
    for (const char* model : {"filtered", "constant", "brdf_only"})
      for (const char* stat : {"_mean", "_max"}) {
        const std::string key = std::string(model) + stat;
        EXPECT_TRUE(b[key].is_number()) << band << " " << key;
        for (const char* term : {"sun", "sky", "refracted"})
          EXPECT_TRUE(b[term][key].is_number()) << band << " " << term << " " << key;
      }
    EXPECT_LE(b["filtered_mean"].get<double>(), b["filtered_max"].get<double>()) << band;
  }
  ASSERT_FALSE(v["rows"].empty());
  for (const char* key : {"reference", "filtered", "constant", "brdf_only", "error_filtered"})
    EXPECT_TRUE(v["rows"][0][key].is_number()) << key;
}

TEST(CliValidate, UnknownViewIsABadInput) {
  const auto r = run("validate --view 3m_nowhere");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("3m_nowhere"), std::string::npos) << r.err;
}
