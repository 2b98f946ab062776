// The grammar of an ASCII STL file, checked before assimp reads it: assimp's reader skips what it
// does not understand, so a typo would otherwise surface as a confusing topology error (or not at
// all). The diagnostic names the line, what was found and what was expected.
//   solid [name]
//     facet normal nx ny nz
//       outer loop
//         vertex x y z      (three times; the numbers on the keyword's line, as after normal)
//       endloop
//     endfacet              (any number of facets)
//   endsolid [name]
// Keywords are lower case (as assimp reads them); numbers are what strtod reads whole (nan and inf
// included: import_mesh refuses those with its own message).
#pragma once

#include <string>
#include <string_view>

namespace rbcsim::mesh {

// Throws InputError(name, "line L: expected ..., got ...") at the first deviation.
void check_ascii_stl_syntax(std::string_view text, const std::string& name);

}  // namespace rbcsim::mesh
