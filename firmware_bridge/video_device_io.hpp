#pragma once
// The system calls a V4L2 camera makes, behind an interface so that a test can play the
// device: a fake answers the ioctls (QUERYCAP, S_FMT, REQBUFS, QBUF/DQBUF…) and scripts
// frames, sequence gaps and timeouts, and the whole camera lifecycle runs without hardware.
// The real implementation forwards each call to the kernel unchanged.
//
// Calls follow the syscall convention (−1 and errno on failure) so V4l2Camera reads exactly
// like code written against the raw calls.
#include <poll.h>
#include <sys/types.h>

#include <cstddef>
#include <cstdint>

namespace cosmos {

class VideoDeviceIo {
 public:
  virtual ~VideoDeviceIo() = default;
  virtual int open(const char* path, int flags) noexcept = 0;
  virtual int close(int fd) noexcept = 0;
  virtual int ioctl(int fd, unsigned long request, void* argument) noexcept = 0;
  virtual void* mmap(std::size_t length, int protection, int flags, int fd,
                     off_t offset) noexcept = 0;
  virtual int munmap(void* address, std::size_t length) noexcept = 0;
  // poll(2) with a µs timeout (ppoll underneath): frame periods are sub-millisecond.
  virtual int poll(pollfd* fds, nfds_t count, std::int64_t timeout_us) noexcept = 0;
};

// The kernel's calls. Stateless: one shared instance serves every camera.
class SystemVideoDeviceIo final : public VideoDeviceIo {
 public:
  int open(const char* path, int flags) noexcept override;
  int close(int fd) noexcept override;
  int ioctl(int fd, unsigned long request, void* argument) noexcept override;
  void* mmap(std::size_t length, int protection, int flags, int fd, off_t offset) noexcept override;
  int munmap(void* address, std::size_t length) noexcept override;
  int poll(pollfd* fds, nfds_t count, std::int64_t timeout_us) noexcept override;
};

VideoDeviceIo& system_video_device_io() noexcept;

}  // namespace cosmos
