#pragma once
// Real-time scheduling inside the HIL guest, where qemu emulates two CPUs and the cell keeps
// them busy: the player's frame thread must queue each frame behind the head before vivid's
// next capture, so it runs SCHED_FIFO above the cell's acquisition thread
// (config/cell-hil.yaml). vivid's own threads stay as they are: they take the driver's mutex
// with trylock and yield in a loop, which as real-time threads would starve its holder.
namespace cosmos::hil {

inline constexpr int kPlayerPriority = 20;

// The calling thread; false when not permitted.
bool run_this_thread_fifo(int priority);

}  // namespace cosmos::hil
