#pragma once
// Working buffers reused by every call on a thread, so that large temporary arrays are not
// allocated afresh (and page-faulted in) each time. A call that finds its thread's buffers in use
// further up its own stack (TBB may run another task of the same loop on a thread that waits in a
// nested parallel region) gets fresh ones of its own.
namespace brdfkit {

template <class T> class ScratchLease {
 public:
  ScratchLease() : shared_(!slot().busy), obj_(shared_ ? slot().obj : own_) {
    if (shared_) slot().busy = true;
  }
  ~ScratchLease() {
    if (shared_) slot().busy = false;
  }
  ScratchLease(const ScratchLease&) = delete;
  ScratchLease& operator=(const ScratchLease&) = delete;
  T& operator*() { return obj_; }
  T* operator->() { return &obj_; }

 private:
  struct Slot {
    T obj;
    bool busy = false;
  };
  static Slot& slot() {
    thread_local Slot s;
    return s;
  }
  bool shared_;
  T own_;
  T& obj_;
};

}  // namespace brdfkit
