// Atomic file writes: a result file either exists complete or not at all.
//
// Everything polydem writes (summary.json, results.h5, .vtu/.pvd) goes first
// to a temporary name beside the final one ("<path>.tmp-<pid>-<n>"), is
// flushed to disk (fsync), and only then renamed onto the final path. rename()
// within one directory is atomic on POSIX file systems, so a reader — or a run
// that crashed half way — never sees a truncated file under the final name.
// The directory is fsynced after the rename so the new name survives a power
// cut as well.
#pragma once

#include <string>

namespace polydem {

// Writes `content` to `path` atomically (temporary file, fsync, rename).
// Throws std::system_error naming the path on any failure; the temporary is
// removed and an existing file at `path` is left untouched.
void write_file_atomic(const std::string& path, const std::string& content);

// A temporary path for writers that need a file name (e.g. the HDF5 library):
// write to path(), then commit() to fsync it and rename it onto final_path().
// If commit() is never called (exception, early return) the destructor
// removes the temporary. Move-only.
class TempPath {
 public:
  explicit TempPath(std::string final_path);
  ~TempPath();
  TempPath(TempPath&& other) noexcept;
  TempPath& operator=(TempPath&& other) noexcept;
  TempPath(const TempPath&) = delete;
  TempPath& operator=(const TempPath&) = delete;

  const std::string& path() const { return temp_; }          // write here
  const std::string& final_path() const { return final_; }   // appears on commit()
  bool committed() const { return committed_; }

  // fsync the temporary, rename it onto final_path(), fsync the directory.
  // Throws std::system_error; after a failure the temporary is still removed
  // by the destructor. Calling commit() twice is an error (std::logic_error).
  void commit();

  // Remove the temporary now (no-op if committed or already gone).
  void discard() noexcept;

 private:
  std::string final_;
  std::string temp_;
  bool committed_ = false;
};

// The temporary name used for `final_path` by this process: unique per call.
std::string temporary_name_for(const std::string& final_path);

// A whole file as bytes ("" if it cannot be read).
std::string read_file_text(const std::string& path);

}  // namespace polydem
