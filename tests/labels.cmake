# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# ctest labels of single GoogleTest cases, read by ctest after the discovered
# tests (TEST_INCLUDE_FILES, tests/CMakeLists.txt; <group>_TESTS are the
# lists gtest_discover_tests made). Each entry is the start of a ctest name
# and must match at least one test, so a renamed test cannot drop out.
#
#  long    the end-to-end cases of more than ~20 s on 2 cores; tools/test.sh
#          runs them after the rest, side by side (ctest -L long).
#  golden  objectives pinned to the last bits of one machine's OpenBLAS
#          kernels (tests/test_engine_baselines.cpp): not a property of the
#          code, so opt-in: OPENBLAS_CORETYPE=SkylakeX ctest -L golden.
set(archgeo_label_long
  "SolverKeys.EveryEnumeratedValueWorksOrIsRefused"
  "BandTightening.BubbleMeetsPlanarityInsideThreeTenthsPercent")
set(archgeo_label_golden "Examples/EngineBaselines.")

set(archgeo_all_tests)
foreach(group tests_energies tests_mesh tests_fields tests_problems tests_cli)
  list(APPEND archgeo_all_tests ${${group}_TESTS})
endforeach()
if(archgeo_all_tests)  # empty before the test executables are built
  foreach(label long golden)
    foreach(start ${archgeo_label_${label}})
      set(found FALSE)
      foreach(test ${archgeo_all_tests})
        string(FIND "${test}" "${start}" at)
        if(at EQUAL 0)
          set_tests_properties("${test}" PROPERTIES LABELS ${label})
          set(found TRUE)
        endif()
      endforeach()
      if(NOT found)
        message(FATAL_ERROR "tests/labels.cmake: no test starts with ${start}")
      endif()
    endforeach()
  endforeach()
endif()
