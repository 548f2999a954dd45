// What XML parsers let pass and a VTK file never has: a second root element, an attribute given
// twice (not well-formed XML; pugixml keeps both and the first would win). Shared by the VTU
// reader and the collection files (.pvtu, .pvd).
#pragma once

#include <pugixml.hpp>

#include <functional>
#include <string>

namespace hoct {

// The first such problem of doc as a message, or "" if none. `where(e)` names element e in the
// message (e.g. "<Piece> at line 4").
std::string xml_structure_problem(const pugi::xml_document &doc,
                                  const std::function<std::string(const pugi::xml_node &)> &where);

} // namespace hoct
