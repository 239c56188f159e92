#pragma once
// Staged outputs (OutputBatch's temporaries) and the folders made for them, removed when the
// process is stopped by SIGINT, SIGTERM or SIGHUP (Ctrl+C, `kill`, a closed terminal), so an
// interrupted run leaves nothing half-written either. The handler is installed on first use,
// only for signals still at their default action (a host's own handlers are left alone); it
// unlinks what is registered (again while a registered folder is not yet empty, for up to 50 ms:
// other threads run on while it does), then ends the process with the same signal.
#include <string>

namespace penumbra::interrupted_outputs {

// Registers a path to remove if the process is stopped; returns a handle for forget(), or -1
// when the table is full (the path is then only cleaned up on a normal exit).
int remember_file(const std::string& path);
// A folder to remove (if empty) after the files; folders are removed in reverse order.
int remember_directory(const std::string& path);
void forget(int handle);

}  // namespace penumbra::interrupted_outputs
