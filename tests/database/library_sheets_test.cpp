// Every material of the library (materials/library/, all three databases) gives a complete sheet from the
// repository alone: its measured panel from its network, labelled with its database, every fit of the grid,
// the figures and a verdict. CTest label "database" (cd build && ctest -L database).
#include "tests/support/library_sheets.h"

#include <gtest/gtest.h>

namespace glossy::test {

TEST(LibrarySheetsAll, EveryMaterialGivesACompleteSheet) { expectCompleteSheets(libraryMaterials()); }

}  // namespace glossy::test
