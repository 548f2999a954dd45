// Atomic file output: write to a temporary file beside the target, then rename over it, so a
// failed or interrupted write never leaves a half-written file under the target's name.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace hoct {

// Calls write(stream) on a temporary file in the target's directory (".NAME.tmp-PID-N", or
// ".hoct.tmp-PID-N" for names near the 255-byte limit), flushes, checks the stream, and renames
// it to `path`. Temporary files of earlier writes of that output whose process no longer exists
// (SIGKILL, a crash) are removed first. On any failure (exception from write, I/O error) the
// temporary file is removed, the target is left untouched, and hoct::Error is thrown naming the
// file. A symbolic link is followed to its final target (the link stays, the target is
// replaced); an existing file's permissions (and owner, where this process may set it) are
// kept; a device or a FIFO is written through, never replaced (its write errors reported: /dev/full
// gives "No space left on device"); a directory is refused.
void write_file_atomic(const std::string &path, const std::function<void(std::ostream &)> &write,
                       bool binary = true);

// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGQUIT that remove the temporary files of the
// writes in progress (a fixed registry of live temporary paths; the handler only calls unlink,
// which is async-signal-safe) and exit at once with status 128 + signal (130 for SIGINT, 143 for
// SIGTERM, 131 for SIGQUIT). An interrupted run thus leaves neither a partial file nor a temporary
// one, and every existing output file keeps its old content. For programs (the CLI), not for
// libraries' users.
void install_interrupt_cleanup();

} // namespace hoct
