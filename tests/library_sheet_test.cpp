// The library renders from the repository alone: one material of each database (materials/library/) gives a
// complete sheet — the measured panel from the network beside its file, labelled with its database, every
// fit of the grid, the figures and a verdict. tests/database/ does the same for all of them (label
// "database").
#include "tests/support/library_sheets.h"

#include <gtest/gtest.h>

namespace glossy::test {

TEST(LibrarySheets, OneMaterialOfEachDatabaseGivesACompleteSheet) {
  // A MERL material outside the six supplement ones, a felt of RGL-EPFL, a glossy Nielsen one.
  expectCompleteSheets({"merl/pink-jasper", "rgl-epfl/acrylic_felt_green", "nielsen2015/paintedmetal"});
}

}  // namespace glossy::test
