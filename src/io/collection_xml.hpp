// The XML of the VTK files that only list others, .pvtu (the pieces of one partitioned grid) and
// .pvd (a collection of data sets over time), and the paths of the files they name.
#pragma once

#include <pugixml.hpp>

#include <string>

namespace hoct {

// A collection file parsed: its <VTKFile> root, checked to be of `type` ("PUnstructuredGrid",
// "Collection"), holding one element `type`. Throws InputError naming the file for an unreadable
// file, XML that is not well formed, an attribute given twice, a second root element, another
// file type or a second such element.
struct CollectionXml {
  pugi::xml_document doc;
  pugi::xml_node element; // the one <type> element under the root
};
void load_collection_xml(const std::string &path, const char *type, CollectionXml &xml);

// `member` (a Source or file attribute of the collection at `collection_path`) as a path: relative
// to the collection's directory, where it must stay (no absolute path, no ".." leading out of
// it), with an extension among `extensions` (".vtu", or ".vtu .pvtu"). Throws InputError
// "<collection>: <what> '<member>' ..." for anything else, and for the collection itself.
std::string collection_member(const std::string &collection_path, const std::string &member,
                              const std::string &what, const std::string &extensions);

// The lowercase extension of path (".vtu").
std::string lowercase_extension(const std::string &path);

} // namespace hoct
