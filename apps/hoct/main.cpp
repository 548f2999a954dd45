#include "commands.hpp"
#include "io/atomic_file.hpp"
#include "memory_guard.hpp"
#include "util/error.hpp"
#include "util/page_pool.hpp"

#include <cstdio>
#include <exception>
#include <iostream>

int main(int argc, char **argv) {
  // An interrupted run (Ctrl-C, kill) removes its temporary files: no partial output is left.
  hoct::install_interrupt_cleanup();
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
  return 0;
}
