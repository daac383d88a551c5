#include "brdfkit/fit/batch/fit_claim.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "brdfkit/core/atomic_file.h"

namespace brdfkit::fit {

namespace fs = std::filesystem;

FitClaim::FitClaim(const fs::path& lock_file, bool wait) {
  std::error_code ec;
  fs::create_directories(lock_file.parent_path(), ec);
  if (ec) throw OutputError(lock_file.parent_path().string(), "cannot create the folder: " + ec.message());
  fd_ = ::open(lock_file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd_ < 0) throw OutputError(lock_file.string(), std::string("cannot be opened: ") + std::strerror(errno));
  int r = 0;
  do {
    r = ::flock(fd_, LOCK_EX | (wait ? 0 : LOCK_NB));
  } while (r != 0 && errno == EINTR);
  held_ = r == 0;
  if (!held_ && errno != EWOULDBLOCK) {
    const int err = errno;
    ::close(fd_);
    throw OutputError(lock_file.string(), std::string("cannot be locked: ") + std::strerror(err));
  }
}

FitClaim::~FitClaim() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

fs::path fit_claim_file(const fs::path& out_dir, const std::string& material, const std::string& model) {
  return out_dir / ".claims" / "fits" / material / (model + ".lock");
}

fs::path summary_claim_file(const fs::path& out_dir) { return out_dir / ".claims" / "summary.lock"; }

bool claimed_elsewhere(const fs::path& lock_file) {
  std::error_code ec;
  if (!fs::exists(lock_file, ec)) return false;
  return !FitClaim(lock_file).held();
}

}  // namespace brdfkit::fit
