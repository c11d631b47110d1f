#include "aapat/temporal/engine/engine_pans.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/sequence/sequence_json.h"

namespace aapat {
namespace {

// Progress: one call per sequence and velocity, done counting up, each pair
// named once; the rows are the same with or without it.
TEST(EnginePans, ReportsEachSequenceAndVelocityOnce) {
  const Metric metric(make_filter("mitchell"), make_acuity("uniform:step=60"), 2);
  const std::vector<Sequence> sequences = {resolve_sequence("halton:frames=4"),
                                           resolve_sequence("r2:frames=4")};
  const std::vector<Vec2> velocities = {{0, 0}, {0.37, 0.21}, {-0.5, 1}};
  const EngineTaa taa = make_engine_taa("bevy", 1, {});
  std::vector<int> done;
  std::set<std::string> notes;
  const auto rows = evaluate_pans(sequences, taa, velocities, metric,
                                  [&](int d, int total, const std::string& note) {
                                    EXPECT_EQ(total, 6);
                                    done.push_back(d);
                                    notes.insert(note);
                                  });
  EXPECT_EQ(done, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(notes.size(), 6u);
  EXPECT_TRUE(notes.count(sequences[1].name + " at 0.37,0.21")) << *notes.begin();
  const auto quiet = evaluate_pans(sequences, taa, velocities, metric);
  for (size_t i = 0; i < rows.rows.size(); ++i)
    for (size_t k = 0; k < velocities.size(); ++k) {
      EXPECT_EQ(rows.rows[i].at[k].mean_e2, quiet.rows[i].at[k].mean_e2);
      EXPECT_EQ(rows.rows[i].at[k].flicker, quiet.rows[i].at[k].flicker);
    }
}

}  // namespace
}  // namespace aapat
