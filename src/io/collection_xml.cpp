#include "io/collection_xml.hpp"

#include "io/file_bytes.hpp"
#include "io/xml_structure.hpp"
#include "util/error.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <vector>

namespace hoct {

namespace fs = std::filesystem;

namespace {

// A collection lists files: a few kilobytes. Larger is not one (or hostile).
constexpr std::size_t kMaxCollectionBytes = std::size_t{64} << 20;

} // namespace

void load_collection_xml(const std::string &path, const char *type, CollectionXml &xml) {
  auto fail = [&](const std::string &what) { throw InputError(path + ": " + what); };
  FileBytes bytes;
  std::string error;
  if (!bytes.read(path, error))
    fail(error);
  if (bytes.empty())
    fail("the file is empty");
  if (bytes.size() > kMaxCollectionBytes)
    fail("a collection of " + std::to_string(bytes.size() >> 20) +
         " MiB: larger than any list of files (64 MiB at most)");
  const pugi::xml_parse_result r = xml.doc.load_buffer(bytes.data(), bytes.size());
  if (!r)
    fail(std::string("not valid XML: ") + r.description() + " at byte " + std::to_string(r.offset));
  if (const std::string problem = xml_structure_problem(
          xml.doc, [](const pugi::xml_node &e) { return "<" + std::string(e.name()) + ">"; });
      !problem.empty())
    fail(problem);
  const pugi::xml_node root = xml.doc.document_element();
  if (std::strcmp(root.name(), "VTKFile") != 0)
    fail("not a VTK XML file (no <VTKFile> element)");
  const std::string file_type = root.attribute("type").as_string();
  if (file_type != type)
    fail("VTK file type is '" + file_type + "', expected " + type);
  xml.element = root.child(type);
  if (!xml.element)
    fail(std::string("no <") + type + "> element");
  if (xml.element.next_sibling(type))
    fail(std::string("a second <") + type + "> element: which one to read is ambiguous");
}

std::string lowercase_extension(const std::string &path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string collection_member(const std::string &collection_path, const std::string &member,
                              const std::string &what, const std::string &extensions) {
  auto fail = [&](const std::string &problem) {
    throw InputError(collection_path + ": " + what + " '" + member + "' " + problem);
  };
  if (member.empty())
    throw InputError(collection_path + ": " + what + " is empty or missing");
  if (member.find('\0') != std::string::npos)
    fail("has a NUL character");
  const fs::path relative(member);
  if (relative.is_absolute() || relative.has_root_name() || relative.has_root_directory())
    fail("is an absolute path: a collection names its files relative to its own directory");
  const fs::path normal = relative.lexically_normal();
  if (!normal.empty() && *normal.begin() == "..")
    fail("is outside the collection's directory: a collection names files in its directory or "
         "below");
  const fs::path dir = fs::path(collection_path).parent_path();
  const fs::path full = (dir / normal).lexically_normal();
  std::error_code ec;
  if (fs::equivalent(full, collection_path, ec) ||
      full == fs::path(collection_path).lexically_normal())
    fail("is the collection itself");
  const std::string ext = lowercase_extension(member);
  std::istringstream allowed(extensions);
  bool ok = false;
  for (std::string e; allowed >> e;)
    ok = ok || e == ext;
  std::string listed = extensions;
  for (std::size_t at = listed.find(' '); at != std::string::npos; at = listed.find(' ', at + 4))
    listed.replace(at, 1, " or ");
  if (!ok)
    fail("is not a " + listed + " file" +
         (ext == ".pvd" ? std::string(" (collections of collections are not read)")
                        : std::string()));
  return full.string();
}

} // namespace hoct
