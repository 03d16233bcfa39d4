#pragma once
// Crash-safe replacement of output files (landmark maps, voxel maps, pictures, stats).
//
// Every file is written to a temp file in the same directory, fsync'ed, renamed over the target
// and the directory fsync'ed: a kill at any moment leaves either the old or the new file, never a
// half-written one. Temp names are unique per process and call, so two processes writing the same
// target never share one: "<dir>/.<stem>.tmp-<pid>-<n><ext>" (the extension is kept because some
// writers choose the format from it, e.g. MRPT's image writer). A temp file is removed on every
// error; only a process killed outright (SIGKILL, power loss) can leave one behind, and
// removeStaleTempFiles sweeps those.

#include <functional>
#include <string>

namespace stairmap::io {

/// A fresh temp name next to `path` (see above); nothing is created.
std::string uniqueTempPath(const std::string& path);

/// True for a file name made by uniqueTempPath (no directory part).
bool isTempFileName(const std::string& filename);

/// Calls `write(temp_path)` to write the whole file, then syncs it and renames it over `path`.
/// Throws std::runtime_error "<path>: <problem> (previous file left unchanged)" if `write` throws
/// or the temp file cannot be synced or renamed; the temp file is removed in every case.
void writeFileAtomic(const std::string& path, const std::function<void(const std::string&)>& write);

/// writeFileAtomic with `text` as the file's content.
void writeTextFileAtomic(const std::string& path, const std::string& text);

/// fsyncs `path` (a file written and closed by someone else). Throws naming the path.
void syncFile(const std::string& path);
/// Renames `from` over `to` and fsyncs their directory. Throws naming both.
void renameDurably(const std::string& from, const std::string& to);

/// Removes the temp files in `dir` left by processes that no longer run (their pid is in the
/// name). Returns how many were removed. Errors are ignored (best effort).
int removeStaleTempFiles(const std::string& dir);

}  // namespace stairmap::io
