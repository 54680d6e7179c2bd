#pragma once
// The heap of a process that runs for months. The recognizer allocates per blob: range
// images, masks and point sets of up to megabytes each, of ever-different sizes. glibc raises
// its mmap threshold after the first such buffer is freed and from then on carves them out of
// the thread's arena, which they fragment: the resident memory creeps up with the hours. A
// fixed threshold maps such buffers whole and unmaps them when freed, and a trim every few
// blobs (realtime.heap_trim_blobs) gives the arenas' free pages back, so the cell's resident
// memory stays flat.
namespace cosmos {

// Once, before the cell's threads start: fixed mmap and trim thresholds (glibc's mallopt;
// nothing elsewhere).
void keep_heap_flat() noexcept;

// Every realtime.heap_trim_blobs blobs, on the recognizer's thread: the heap's free pages
// back to the system (glibc's malloc_trim; nothing elsewhere).
void return_free_heap_pages() noexcept;

}  // namespace cosmos
