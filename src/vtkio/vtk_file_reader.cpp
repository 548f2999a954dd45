#include "vtkio/vtk_file_reader.hpp"

#include "io/external_reader.hpp"
#include "io/piece_join.hpp"
#include "io/pvtu_reader.hpp"
#include "io/vtk_cells.hpp"
#include "util/error.hpp"
#include "vtkio/exodus_reader.hpp"
#include "vtkio/grid_input.hpp"
#include "vtkio/xdmf_copy.hpp"

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkInformation.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkVersion.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXdmf3Reader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sys/stat.h>

namespace hoct::vtkio {
namespace {

enum class Kind { Legacy, XmlGrid, XmlMultiBlock, Xdmf, Exodus };

struct Format {
  Kind kind;
  VtkFormat format;
};

const std::vector<Format> &formats() {
  static const std::vector<Format> f = {
      {Kind::Legacy, {{".vtk"}, "legacy VTK (unstructured grid or polydata)"}},
      {Kind::XmlMultiBlock, {{".vtm"}, "VTK XML multiblock (its unstructured-grid blocks)"}},
      {Kind::Xdmf, {{".xdmf", ".xmf", ".xdmf3"}, "XDMF 3 with HDF5 (DOLFINx's XDMFFile)"}},
      {Kind::Exodus,
       {{".e", ".exo", ".ex2", ".exii", ".g", ".gen"}, "Exodus II (MOOSE, Cubit, SEACAS)"}},
  };
  return f;
}

std::string lower_extension(const std::string &path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::optional<Kind> kind_of(const std::string &path) {
  const std::string ext = lower_extension(path);
  if (ext == ".vtu")
    return Kind::XmlGrid;
  for (const Format &f : formats())
    for (const std::string &e : f.format.extensions)
      if (e == ext)
        return f.kind;
  return std::nullopt;
}

// VTK's messages while a reader runs, kept instead of printed: VTK reports a bad file through
// its output window (and some readers only there), hoct through one InputError.
class MessageCollector : public vtkOutputWindow {
public:
  static MessageCollector *New();
  vtkTypeMacro(MessageCollector, vtkOutputWindow);
  void DisplayText(const char *text) override { keep(text, false); }
  void DisplayErrorText(const char *text) override { keep(text, true); }
  void DisplayWarningText(const char *text) override { keep(text, false); }
  void DisplayGenericWarningText(const char *text) override { keep(text, false); }
  void DisplayDebugText(const char *) override {}
  std::vector<std::string> errors, warnings;

private:
  void keep(const char *text, bool error) {
    (error ? errors : warnings).push_back(clean(text ? text : ""));
  }
  // "ERROR: In /build/.../vtkXMLReader.cxx, line 123\nvtkXMLUnstructuredGridReader (0x55..):
  // Error parsing XML ..." -> "vtkXMLUnstructuredGridReader: Error parsing XML ..."
  static std::string clean(std::string t) {
    if (t.rfind("ERROR: In ", 0) == 0 || t.rfind("Warning: In ", 0) == 0 ||
        t.rfind("Generic Warning: In ", 0) == 0) {
      const std::size_t nl = t.find('\n');
      t = nl == std::string::npos ? std::string() : t.substr(nl + 1);
    }
    const std::size_t open = t.find(" (0x");
    if (open != std::string::npos) {
      const std::size_t close = t.find("): ", open);
      if (close != std::string::npos)
        t = t.substr(0, open) + ": " + t.substr(close + 3);
    }
    while (!t.empty() && (t.back() == '\n' || t.back() == ' ' || t.back() == '\r'))
      t.pop_back();
    for (char &c : t)
      if (c == '\n')
        c = ' ';
    return t;
  }
};
vtkStandardNewMacro(MessageCollector);

// Installs a collector as VTK's output window for its lifetime (one read at a time).
class CollectMessages {
public:
  // VTK's logger prints errors on stderr too (besides the output window): off meanwhile.
  CollectMessages()
      : previous_(vtkOutputWindow::GetInstance()),
        verbosity_(vtkLogger::GetCurrentVerbosityCutoff()) {
    vtkOutputWindow::SetInstance(collector_);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~CollectMessages() {
    vtkOutputWindow::SetInstance(previous_);
    vtkLogger::SetStderrVerbosity(verbosity_);
  }
  CollectMessages(const CollectMessages &) = delete;
  CollectMessages &operator=(const CollectMessages &) = delete;
  MessageCollector &messages() { return *collector_; }

private:
  vtkSmartPointer<vtkOutputWindow> previous_;
  vtkLogger::Verbosity verbosity_;
  vtkNew<MessageCollector> collector_;
};

std::string vtk_name() { return std::string("VTK ") + vtkVersion::GetVTKVersion(); }

// The data set blocks of VTK's output, with their names ("block 2 'left'").
struct Block {
  vtkDataSet *data;
  std::string name;
};

std::vector<Block> blocks_of(vtkDataObject *out) {
  std::vector<Block> blocks;
  if (auto *ds = vtkDataSet::SafeDownCast(out)) {
    blocks.push_back({ds, ""});
  } else if (auto *cd = vtkCompositeDataSet::SafeDownCast(out)) {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cd->NewIterator());
    int k = 0;
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem(), ++k) {
      auto *ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      if (!ds)
        continue;
      std::string name = "block " + std::to_string(k);
      if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
        name +=
            std::string(" '") + it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME()) + "'";
      blocks.push_back({ds, name});
    }
  }
  return blocks;
}

// The first bytes of the file, to refuse what is not the format before VTK's readers, some of
// which crash on arbitrary bytes or print only.
void check_file(const std::string &path, Kind kind) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(path + ": cannot open (no such file)");
  if (!S_ISREG(st.st_mode))
    throw InputError(path + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path + ": cannot open for reading");
  std::string head(512, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.empty())
    throw InputError(path + ": the file is empty");
  switch (kind) {
  case Kind::Legacy:
    if (head.rfind("# vtk DataFile Version", 0) != 0)
      throw InputError(path + ": not a legacy VTK file (it does not start with \"# vtk "
                              "DataFile Version\")");
    break;
  case Kind::XmlGrid:
  case Kind::XmlMultiBlock:
  case Kind::Xdmf:
    if (head.find('<') == std::string::npos)
      throw InputError(path + ": not an XML file");
    break;
  case Kind::Exodus: // netCDF classic ("CDF\1", "CDF\2", "CDF\5") or netCDF-4 (HDF5)
    if (head.rfind("CDF", 0) != 0 && head.rfind("\x89HDF\r\n\x1a\n", 0) != 0)
      throw InputError(path + ": not an Exodus II file (neither netCDF nor HDF5)");
    break;
  }
}

vtkSmartPointer<vtkAlgorithm> make_reader(const std::string &path, Kind kind) {
  switch (kind) {
  case Kind::Legacy: {
    auto r = vtkSmartPointer<vtkDataSetReader>::New();
    r->SetFileName(path.c_str());
    r->ReadAllScalarsOn();
    r->ReadAllVectorsOn();
    r->ReadAllFieldsOn();
    return r;
  }
  case Kind::XmlGrid: {
    auto r = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  case Kind::XmlMultiBlock: {
    auto r = vtkSmartPointer<vtkXMLMultiBlockDataReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  case Kind::Xdmf: {
    auto r = vtkSmartPointer<vtkXdmf3Reader>::New();
    r->SetFileName(path.c_str()); // an XdmfForReading's path
    return r;
  }
  case Kind::Exodus: // read by exodus_reader
    break;
  }
  return nullptr;
}

// VTK's first error as the reason, or the fallback text.
[[noreturn]] void fail_with(const std::string &path, MessageCollector &m,
                            const std::string &fallback) {
  std::string why = m.errors.empty() ? fallback : m.errors.front();
  if (m.errors.size() > 1)
    why += " (and " + std::to_string(m.errors.size() - 1) + " more error" +
           (m.errors.size() > 2 ? "s" : "") + ")";
  throw InputError(path + ": " + vtk_name() + " could not read it: " + why);
}

struct VtkRead {
  std::vector<FilePiece> pieces;
  std::vector<std::string> skipped; // blocks without the field
  std::string detail;               // the time step read
};

VtkRead read_pieces(const std::string &path, Kind kind, const FieldSelection &field,
                    FileContents *contents) {
  check_file(path, kind);
  std::optional<XdmfForReading> xdmf;
  if (kind == Kind::Xdmf)
    xdmf.emplace(path);
  CollectMessages collect;
  MessageCollector &m = collect.messages();
  vtkSmartPointer<vtkAlgorithm> reader = make_reader(xdmf ? xdmf->path() : path, kind);
  try {
    reader->UpdateInformation();
  } catch (const std::exception &e) { // the Xdmf library throws XdmfError
    throw InputError(path + ": " + vtk_name() + " could not read it: " + e.what());
  }
  if (!m.errors.empty())
    fail_with(path, m, "");
  std::vector<double> times;
  vtkInformation *info = reader->GetOutputInformation(0);
  if (info && info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS())) {
    const int n = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    const double *t = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    times.assign(t, t + n);
  }
  VtkRead r;
  try {
    // A time is always requested where there are times: without one, the Xdmf reader gives an
    // empty grid for a temporal collection of one step.
    if (times.size() > 1 || (!field.default_step() && !times.empty())) {
      const std::size_t step = choose_step(path, {times.begin(), times.end()}, field, "the file");
      reader->UpdateTimeStep(times[step]);
      r.detail = step_description(step, times.size(), times[step]);
    } else if (!times.empty()) {
      reader->UpdateTimeStep(times.front());
    } else if (!field.default_step()) {
      throw InputError(path + ": --step / --time: the file holds one time step");
    } else {
      reader->Update();
    }
  } catch (const InputError &) {
    throw;
  } catch (const std::exception &e) { // the Xdmf library throws XdmfError
    throw InputError(path + ": " + vtk_name() + " could not read it: " + e.what());
  }
  vtkDataObject *out = reader->GetOutputDataObject(0);
  if (!m.errors.empty() || !out)
    fail_with(path, m, "the reader gave no data");
  const std::vector<Block> blocks = blocks_of(out);
  // The field: from the first block that has it; the blocks without it are left out (an XDMF
  // file's mesh next to its functions) and named.
  std::string chosen, problem;
  for (const Block &b : blocks) {
    std::string why;
    if (vtkDataArray *a = find_point_array(b.data->GetPointData(), field, &why)) {
      chosen = a->GetName() ? a->GetName() : "";
      break;
    }
    if (problem.empty() && b.data->GetNumberOfPoints() > 0)
      problem = (b.name.empty() ? "" : b.name + ": ") + why;
  }
  if (contents) {
    for (const Block &b : blocks) {
      vtkPointData *pd = b.data->GetPointData();
      for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
        vtkAbstractArray *a = pd->GetAbstractArray(i);
        const std::string name = a->GetName() ? a->GetName() : "";
        if (std::any_of(contents->fields.begin(), contents->fields.end(),
                        [&](const FileField &f) { return f.name == name; }))
          continue;
        FileField f;
        f.name = name;
        f.kind = "point data";
        f.components = a->GetNumberOfComponents();
        for (std::size_t k = 0; k < times.size(); ++k)
          f.steps.push_back({static_cast<int64_t>(k), times[k]});
        contents->fields.push_back(std::move(f));
      }
    }
  }
  if (chosen.empty())
    throw InputError(path + ": " + (problem.empty() ? "no point data" : problem) +
                     (field.name.empty() && problem.find("arrays: none") == std::string::npos
                          ? ": name one with --scalar"
                          : ""));
  for (const Block &b : blocks) {
    const std::string where = path + (b.name.empty() ? "" : ", " + b.name);
    vtkDataArray *a = b.data->GetPointData()->GetArray(chosen.c_str());
    if (!a) {
      if (b.data->GetNumberOfCells() > 0)
        r.skipped.push_back(b.name.empty() ? "the data set" : b.name);
      continue;
    }
    r.pieces.push_back(grid_piece(b.data, a, field.component, where));
  }
  return r;
}

MeshInput read_piece(const std::string &path, const FieldSelection &field, const ReadLimits &limits,
                     const VtuPieceRequest &request, VtuPieceArrays &arrays) {
  VtkRead r = read_pieces(path, Kind::XmlGrid, field, nullptr);
  if (r.pieces.size() != 1)
    throw InputError(path + ": expected one unstructured grid");
  FilePiece &p = r.pieces.front();
  check_memory(limits, p.input.num_points(), p.input.num_cells(), p.input.cell_nodes.size(), path);
  if (p.input.num_cells() == 0 && !(request.allow_empty && p.input.points.empty()))
    throw InputError(path + ": " + kVtkSurfaceCells);
  arrays = std::move(p.arrays);
  p.input.source = path;
  return std::move(p.input);
}

} // namespace

MeshInput read_vtk_file(const std::string &path, const FieldSelection &field,
                        const ReadLimits &limits, FileContents *contents) {
  const std::optional<Kind> kind = kind_of(path);
  if (!kind)
    throw InputError(path + ": not a format read through VTK");
  if (*kind == Kind::Exodus) { // the Exodus library itself: doubles, TRI7
    check_file(path, *kind);
    return read_exodus(path, field, limits, contents);
  }
  VtkRead r = read_pieces(path, *kind, field, contents);
  std::size_t cells = 0, points = 0, nodes = 0;
  for (const FilePiece &p : r.pieces) {
    cells += p.input.num_cells();
    points += p.input.num_points();
    nodes += p.input.cell_nodes.size();
  }
  check_memory(limits, points, cells, nodes, path);
  if (cells == 0)
    throw InputError(path + ": " + kVtkSurfaceCells + " in what " + vtk_name() + " read");
  MeshInput m;
  if (r.pieces.size() == 1) { // one grid: read as it is, ghost cells kept (a piece read alone)
    const VtuPieceArrays &a = r.pieces.front().arrays;
    m = std::move(r.pieces.front().input);
    if (a.ghost_cells > 0 || a.ghost_points > 0)
      m.warnings.push_back(lone_piece_warning(path, a.ghost_cells, a.ghost_points));
  } else { // blocks: joined as pieces (ghost copies dropped, shared points merged)
    std::vector<FilePiece> kept;
    for (FilePiece &p : r.pieces)
      if (p.input.num_cells() > 0)
        kept.push_back(std::move(p));
    m = join_pieces(std::move(kept), path, true, limits.threads);
  }
  m.source = path;
  m.field_detail = r.detail.empty() ? std::string() : "(" + r.detail + ")";
  if (!r.skipped.empty()) {
    std::string list;
    for (std::size_t i = 0; i < r.skipped.size() && i < 6; ++i)
      list += (i ? ", " : "") + r.skipped[i];
    if (r.skipped.size() > 6)
      list += " and " + std::to_string(r.skipped.size() - 6) + " more";
    m.warnings.push_back(path + ": " + list + " ha" + (r.skipped.size() == 1 ? "s" : "ve") +
                         " no point array '" + m.field_name + "' and " +
                         (r.skipped.size() == 1 ? "is" : "are") + " left out");
  }
  if (*kind == Kind::Xdmf &&
      std::all_of(m.cell_degree.begin(), m.cell_degree.end(), [](uint8_t d) { return d == 1; }))
    m.warnings.push_back(
        path + ": XDMF holds values at the mesh's nodes only, and this mesh is linear: the tree is "
               "that of the piecewise-linear field. A higher-order function written with "
               "XDMFFile was interpolated to the vertices first; write it with VTXWriter or "
               "VTKFile (.pvd) to keep its degree.");
  return m;
}

const std::vector<VtkFormat> &vtk_formats() {
  static const std::vector<VtkFormat> f = [] {
    std::vector<VtkFormat> v;
    for (const Format &x : formats())
      v.push_back(x.format);
    return v;
  }();
  return f;
}

void register_vtk_reader() {
  ExternalReader r;
  r.name = vtk_name();
  std::string listed;
  for (const VtkFormat &f : vtk_formats()) {
    std::string exts;
    for (const std::string &e : f.extensions) {
      r.extensions.push_back(e);
      exts += (exts.empty() ? "" : " ") + e;
    }
    listed += (listed.empty() ? "" : ", ") + exts + " " + f.description;
  }
  r.formats = listed + ", .vtu with LZ4 or LZMA compression";
  r.read = read_vtk_file;
  r.read_vtu_piece = read_piece;
  set_external_reader(std::move(r));
}

} // namespace hoct::vtkio
