// Sheets of library materials checked for completeness (tests/library_sheet_test.cpp, tests/database/).
#pragma once

#include <string>
#include <vector>

namespace glossy::test {

// Every material of the library as "DATABASE/NAME", sorted.
std::vector<std::string> libraryMaterials();

// Renders `materials` ("DATABASE/NAME") with one `glossy sheets` at a small size, with no MERL folder, and
// checks each sheet: a measured panel that is not empty and whose data carries its database's label, every
// panel of the grid rendered, the figures written and a verdict (not "no verdict: ...").
void expectCompleteSheets(const std::vector<std::string>& materials);

}  // namespace glossy::test
