#pragma once
// Hands the allocator's free memory back to the system.
//
// A batch of fits frees ~100 MB grids and bases on one thread after another allocated them on
// others; glibc keeps such memory in its per-thread arenas (a free chunk below a live one is never
// trimmed), so a long batch's resident size grows with the number of fits, not with the fits in
// flight. malloc_trim(0) releases the free pages of every arena (madvise), at the cost of one walk
// over the free lists: call it between fits, not inside one.
namespace brdfkit {

void return_free_memory();

}  // namespace brdfkit
