#include "firmware_bridge/video_device_io.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos {

int SystemVideoDeviceIo::open(const char* path, int flags) noexcept { return ::open(path, flags); }

int SystemVideoDeviceIo::close(int fd) noexcept { return ::close(fd); }

int SystemVideoDeviceIo::ioctl(int fd, unsigned long request, void* argument) noexcept {
  // A signal landing in the middle of an ioctl is not a device error: repeat the call.
  int result = 0;
  do {
    result = ::ioctl(fd, request, argument);
  } while (result == -1 && errno == EINTR);
  return result;
}

void* SystemVideoDeviceIo::mmap(std::size_t length, int protection, int flags, int fd,
                                off_t offset) noexcept {
  return ::mmap(nullptr, length, protection, flags, fd, offset);
}

int SystemVideoDeviceIo::munmap(void* address, std::size_t length) noexcept {
  return ::munmap(address, length);
}

int SystemVideoDeviceIo::poll(pollfd* fds, nfds_t count, std::int64_t timeout_us) noexcept {
  const timespec timeout = ns_to_timespec(timeout_us * 1000);
  return ::ppoll(fds, count, timeout_us < 0 ? nullptr : &timeout, nullptr);
}

VideoDeviceIo& system_video_device_io() noexcept {
  static SystemVideoDeviceIo io;
  return io;
}

}  // namespace cosmos
