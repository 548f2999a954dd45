#include "io/xml_structure.hpp"

#include <cstring>
#include <vector>

namespace hoct {

std::string xml_structure_problem(const pugi::xml_document &doc,
                                  const std::function<std::string(const pugi::xml_node &)> &where) {
  pugi::xml_node root;
  for (const pugi::xml_node n : doc.children()) {
    if (n.type() != pugi::node_element)
      continue;
    if (root)
      return "a second root element " + where(n) + " after <" + root.name() +
             ">: an XML file has one (a VTK file's is <VTKFile>)";
    root = n;
  }
  // Every element's attributes, once each (depth first; the elements are few: the arrays' data
  // are text, not elements).
  std::vector<pugi::xml_node> todo;
  if (root)
    todo.push_back(root);
  while (!todo.empty()) {
    const pugi::xml_node e = todo.back();
    todo.pop_back();
    for (pugi::xml_attribute a = e.first_attribute(); a; a = a.next_attribute())
      for (pugi::xml_attribute b = a.next_attribute(); b; b = b.next_attribute())
        if (std::strcmp(a.name(), b.name()) == 0)
          return where(e) + " has the attribute " + a.name() + " twice ('" + a.value() + "' and '" +
                 b.value() + "'): not well-formed XML (an attribute is given once)";
    for (const pugi::xml_node c : e.children())
      if (c.type() == pugi::node_element)
        todo.push_back(c);
  }
  return {};
}

} // namespace hoct
