// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// "Did you mean" (core/closest_name.h): edit distance and the nearest name.
#include "core/closest_name.h"

#include <gtest/gtest.h>

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

TEST(ClosestName, EditDistanceCountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(EditDistance("", ""), 0u);
  EXPECT_EQ(EditDistance("solve", "solve"), 0u);
  EXPECT_EQ(EditDistance("slove", "solve"), 2u);  // a swap is two substitutions
  EXPECT_EQ(EditDistance("treads", "threads"), 1u);
  EXPECT_EQ(EditDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(EditDistance("abc", ""), 3u);
  EXPECT_EQ(EditDistance("", "abc"), 3u);
}

TEST(ClosestName, FindsTheNearestNameOrItsTailWithinTheEdits) {
  const std::vector<std::string> keys = {"num_threads", "max_num_iterations", "function_tolerance"};
  EXPECT_EQ(ClosestName("treads", keys), "num_threads");           // a tail, one edit
  EXPECT_EQ(ClosestName("max_num_iteration", keys), "max_num_iterations");
  EXPECT_EQ(ClosestName("iterations", keys), "max_num_iterations");  // a tail exactly
  EXPECT_EQ(ClosestName("frobnicate", keys), "");
  EXPECT_EQ(ClosestName("tolerances", keys, 0), "");  // one edit away, none allowed
  EXPECT_EQ(ClosestName("x", {"y", "z"}), "");        // as many edits as characters
  EXPECT_EQ(ClosestName("solv", {"solve", "spec"}), "solve");
  EXPECT_EQ(ClosestName("ab", {"abc", "abd"}), "abc");  // a tie: the first
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
