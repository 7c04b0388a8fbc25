#include "io/atomic_file.hpp"

#include <sstream>

#include <fstream>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace polydem {
namespace {

[[noreturn]] void throw_errno(const std::string& what, const std::string& path) {
  throw std::system_error(errno, std::generic_category(), what + " '" + path + "'");
}

// Directory holding `path` ("." when there is no slash).
std::string parent_dir(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

void fsync_path(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) throw_errno("cannot open for fsync", path);
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    errno = err;
    throw_errno("fsync failed for", path);
  }
  ::close(fd);
}

// Make a rename durable. Some file systems refuse fsync on a directory
// (EINVAL); the rename itself has happened then, so that is not an error.
void fsync_directory(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

void rename_or_throw(const std::string& from, const std::string& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) throw_errno("cannot rename '" + from + "' to", to);
  fsync_directory(parent_dir(to));
}

}  // namespace

std::string temporary_name_for(const std::string& final_path) {
  static std::atomic<unsigned long> counter{0};
  return final_path + ".tmp-" + std::to_string(static_cast<long>(::getpid())) + "-" +
         std::to_string(counter.fetch_add(1));
}

void write_file_atomic(const std::string& path, const std::string& content) {
  TempPath tmp(path);
  const int fd = ::open(tmp.path().c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw_errno("cannot create", tmp.path());
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      errno = err;
      throw_errno("cannot write", tmp.path());
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) throw_errno("cannot close", tmp.path());
  tmp.commit();  // fsync, rename, fsync the directory
}

TempPath::TempPath(std::string final_path) : final_(std::move(final_path)) {
  if (!final_.empty()) temp_ = temporary_name_for(final_);
}

TempPath::~TempPath() { discard(); }

TempPath::TempPath(TempPath&& other) noexcept
    : final_(std::move(other.final_)), temp_(std::move(other.temp_)), committed_(other.committed_) {
  other.temp_.clear();
  other.committed_ = true;
}

TempPath& TempPath::operator=(TempPath&& other) noexcept {
  if (this != &other) {
    discard();
    final_ = std::move(other.final_);
    temp_ = std::move(other.temp_);
    committed_ = other.committed_;
    other.temp_.clear();
    other.committed_ = true;
  }
  return *this;
}

void TempPath::commit() {
  if (committed_) throw std::logic_error("TempPath::commit called twice for '" + final_ + "'");
  if (temp_.empty()) throw std::logic_error("TempPath::commit on an empty TempPath");
  fsync_path(temp_, O_RDONLY);
  rename_or_throw(temp_, final_);
  committed_ = true;
}

void TempPath::discard() noexcept {
  if (!committed_ && !temp_.empty()) ::unlink(temp_.c_str());  // ENOENT is fine
  temp_.clear();
}

std::string read_file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace polydem
