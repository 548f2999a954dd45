#include "commands.hpp"
#include "io/atomic_file.hpp"
#include "memory_guard.hpp"
#include "util/error.hpp"
#include "util/page_pool.hpp"
#ifdef HOCT_WITH_VTK
#include "vtkio/vtk_file_reader.hpp"
#endif

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

namespace {

// Everything a command printed reached its destination: the final flush and close of the
// standard output are checked (a full disk, /dev/full, a file system that fails on close), so
// that a lost report is an error, not exit status 0.
int finish_standard_output() {
  std::cout.flush();
  errno = 0;
  const bool flush_failed = std::fflush(stdout) != 0;
  int err =
      errno; // the reason, when the last buffer's write failed (earlier ones are only flagged)
  bool failed = flush_failed || std::ferror(stdout) || !std::cout.good();
  if (!failed) {
    errno = 0;
    failed = std::fclose(stdout) != 0;
    err = errno;
  }
  if (!failed)
    return 0;
  std::fprintf(stderr, "hoct: error: writing the standard output failed%s%s\n", err ? ": " : "",
               err ? std::strerror(err) : "");
  return 1;
}

} // namespace

int main(int argc, char **argv) {
  // An interrupted run (Ctrl-C, kill) removes its temporary files: no partial output is left.
  hoct::install_interrupt_cleanup();
#ifdef HOCT_WITH_VTK
  hoct::vtkio::register_vtk_reader(); // legacy .vtk, XDMF, Exodus II, LZ4/LZMA .vtu
#endif
  CLI::App app{"hoct: exact contour trees of piecewise-polynomial fields on triangle meshes"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hoct 0.1.0");
  hoct::cli::register_info(app);
  hoct::cli::register_generate(app);
  hoct::cli::register_eval(app);
  hoct::cli::register_tree(app);
  hoct::cli::register_compare(app);
  hoct::cli::register_render(app);
  hoct::cli::register_study(app);
  hoct::cli::register_convert(app);
  hoct::cli::add_max_memory_option(app); // after every command is registered
  hoct::cli::register_check(app);
  // One page-reuse scope for the whole command: the pages of arrays freed on the way (the input
  // the mesh build consumes, the build's scratch) serve the arrays allocated after them instead
  // of going back to the system and being faulted in (and zeroed) again.
  const hoct::PageReuseScope reuse_pages;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError &e) {
    return app.exit(e);
  } catch (const hoct::Error &e) {
    std::cerr << "hoct: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc &) {
    std::cerr << "hoct: error: out of memory\n";
    return 1;
  } catch (const std::exception &e) {
    std::cerr << "hoct: internal error: " << e.what() << "\n";
    return 2;
  }
  return finish_standard_output();
}
