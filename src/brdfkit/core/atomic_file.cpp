#include "brdfkit/core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <streambuf>

namespace brdfkit {

namespace fs = std::filesystem;

namespace {

// A stream buffer over a file descriptor that keeps the errno of the first failed write(2), so
// a full disk (ENOSPC) or a file size limit (EFBIG) is named in the message; std::ofstream drops it.
class FdBuffer : public std::streambuf {
 public:
  explicit FdBuffer(int fd) : fd_(fd) { setp(buf_.data(), buf_.data() + buf_.size()); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) sputc(traits_type::to_char_type(c));
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    if (error_) return false;
    for (const char* p = pbase(); p < pptr();) {
      const ssize_t n = ::write(fd_, p, size_t(pptr() - p));
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        error_ = errno;
        return false;
      }
      p += n;
    }
    setp(buf_.data(), buf_.data() + buf_.size());
    return true;
  }

  int fd_;
  int error_ = 0;
  std::array<char, 1 << 16> buf_;
};

std::string cannot_write(int err) { return std::string("cannot be written: ") + std::strerror(err); }

// Writes the temporary `tmp` completely, closed; OutputError naming `path` otherwise.
void write_temporary(const fs::path& path, const fs::path& tmp, const std::function<void(std::ostream&)>& write) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw OutputError(path.string(), cannot_write(errno));
  FdBuffer buf(fd);
  std::ostream out(&buf);
  write(out);
  out.flush();
  int err = buf.error();
  if (!err && !out) err = EIO;  // the writer itself failed without a system error
  // close(2) reports what a network file system defers (ENOSPC, EDQUOT).
  if (::close(fd) != 0 && !err) err = errno;
  if (err) throw OutputError(path.string(), cannot_write(err));
}

}  // namespace

void check_output_file(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw OutputError(path.string(), "is a folder; give the path of a file to write");
  const fs::path folder = path.parent_path();
  if (!folder.empty() && !fs::is_directory(folder, ec))
    throw OutputError(path.string(), "cannot be written: there is no folder " + folder.string());
}

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  check_output_file(path);
  const fs::path tmp = path.string() + ".tmp." + std::to_string(::getpid());
  try {
    write_temporary(path, tmp, write);
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw OutputError(path.string(), "cannot be replaced: " + ec.message());
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
}

void write_file_atomically(const std::filesystem::path& path, const std::string& contents) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(contents.data(), std::streamsize(contents.size())); });
}

void remove_temporaries_of(const fs::path& path) {
  const std::string prefix = path.filename().string() + ".tmp.";
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0) fs::remove(e.path(), ec);
  }
}

}  // namespace brdfkit
