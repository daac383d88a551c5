#pragma once
// Claims: advisory locks that let several batches (processes, or threads of one process) share an
// output folder. A claim is flock(2) on a lock file, held through an open file descriptor: the
// kernel releases it when the descriptor closes, and so when its process dies, even by SIGKILL,
// so a claim is never left stale. flock locks belong to an open file description, so two claims
// of one file exclude each other within one process too. The lock files stay (empty): removing
// one while another process has it open but not yet locked would let two holders coexist.
#include <filesystem>
#include <string>

namespace brdfkit::fit {

class FitClaim {
 public:
  // Tries to claim `lock_file` without waiting (LOCK_EX | LOCK_NB); wait = true waits for it.
  // The file and its folders are created. OutputError when the file cannot be created or opened.
  explicit FitClaim(const std::filesystem::path& lock_file, bool wait = false);
  ~FitClaim();
  FitClaim(const FitClaim&) = delete;
  FitClaim& operator=(const FitClaim&) = delete;

  bool held() const { return held_; }

 private:
  int fd_ = -1;
  bool held_ = false;
};

// The lock file of one fit and of the summary, under OUTDIR/.claims/ (no material name can reach
// into it: fits/ holds one folder per material, summary.lock is a file beside it).
std::filesystem::path fit_claim_file(const std::filesystem::path& out_dir, const std::string& material,
                                     const std::string& model);
std::filesystem::path summary_claim_file(const std::filesystem::path& out_dir);

// True when another claim holds `lock_file` now (probed by claiming it for an instant).
bool claimed_elsewhere(const std::filesystem::path& lock_file);

}  // namespace brdfkit::fit
