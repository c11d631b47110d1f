// Output files are written whole or not at all: the content goes to a
// temporary file in the same folder, which is then renamed over the target.
//
// A command writes all its files or none: while an OutputTransaction is open
// the renames wait for its commit, and a transaction that ends without one
// (an error, an exception) deletes what it staged. Temporary files are also
// removed when SIGINT or SIGTERM ends the process mid-write.
#pragma once

#include <string>
#include <string_view>

#include "aapat/core/read_file.h"  // read_file, for the file inputs of this layer

namespace aapat {

// Writes `content` to `path` whole or not at all. Inside an open transaction
// the file appears at commit, and a path already staged (by any spelling) or
// a folder is refused at once: two outputs of one command name one file.
void write_file_atomically(const std::string& path, std::string_view content);
// The same, but the file appears now (an input another program reads, a cache
// entry); inside a transaction, a file that did not exist before is deleted
// again if the transaction does not commit, unless `keep_on_rollback`.
void write_file_now(const std::string& path, std::string_view content,
                    bool keep_on_rollback = false);

// Deletes the temporaries (NAME.tmp.PID.N) in `dir` that a killed writer
// left: those whose process is gone and that are over ten minutes old (a
// writer on another machine sharing the folder is not seen by PID). Safe
// while other processes write there.
void remove_orphaned_temporaries(const std::string& dir);

// Removes `path` when the open transaction commits (now when none is open):
// an earlier run's output that this run's set of outputs no longer holds.
void remove_file_at_commit(const std::string& path);

// Creates `path` (and its parents) as a folder, or checks that it is one;
// throws Error naming `what` when it is a file or cannot be made. Inside a
// transaction that rolls back, the folders it made are removed again if empty.
void ensure_directory(const std::string& path, std::string_view what);

// Checks, before any work, that `path` can become the folder `ensure_directory`
// makes: it is a writable folder, or nothing is there yet.
void check_directory_target(const std::string& path, std::string_view what);

// Checks, before any work, that `path` can be written as a file: its folder
// exists, is a folder and can be written, and `path` is not a folder.
void check_file_target(const std::string& path, std::string_view what);

// One command's outputs: all of them or none. At most one is open at a time.
class OutputTransaction {
 public:
  OutputTransaction();
  ~OutputTransaction();  // rolls back unless committed
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;
  // Renames every staged file onto its target, in the order written.
  void commit();
};

// From now on writes and folders are not made: a process of an MPI job other
// than rank 0, which computes what rank 0 writes (src/cluster).
void mute_outputs();

// Installs SIGINT and SIGTERM handlers that delete the temporary files of
// writes in flight, then end the process as the signal would.
void remove_temporaries_on_signals();

}  // namespace aapat
