#include "core/io/model_base_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "core/input_error.hpp"
#include "core/io/model_base_payload.hpp"
#include "core/io/parameters_text.hpp"
#include "core/io/xxh64.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'C', 'O', 'S', 'M', 'O', 'S', 'M', 'B'};
// FlatBuffers addresses its buffer with 32-bit offsets.
constexpr std::size_t kMaxPayloadBytes = (std::size_t{1} << 31) - 1;

struct Header {
  std::uint32_t format_version = 0;
  std::uint32_t header_bytes = 0;
  std::uint64_t payload_bytes = 0;
  std::uint64_t payload_checksum = 0;
};

void put_le(unsigned char* out, std::uint64_t value, int bytes) {
  for (int k = 0; k < bytes; ++k) out[k] = static_cast<unsigned char>(value >> (8 * k));
}

std::uint64_t get_le(const unsigned char* in, int bytes) {
  std::uint64_t value = 0;
  for (int k = 0; k < bytes; ++k) value |= static_cast<std::uint64_t>(in[k]) << (8 * k);
  return value;
}

std::string hex(std::uint64_t value) {
  char text[19];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(value));
  return text;
}

[[noreturn]] void refuse(const fs::path& path, const std::string& reason) {
  throw InputError(path.string() + ": " + reason);
}

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

void write_all(std::FILE* file, const void* data, std::size_t bytes, const fs::path& path) {
  if (std::fwrite(data, 1, bytes, file) != bytes)
    refuse(path, std::string("cannot write: ") + std::strerror(errno));
}

// The whole file, mapped read-only: the pages are the file's (the page cache's), read as the
// checksum and the verifier walk them, never copied; page-aligned, so the payload's doubles
// are aligned (the header is 32 bytes). A base is replaced only by renaming a new file over
// it (write_model_base), which leaves the mapped one intact.
struct FileBytes {
  std::shared_ptr<const void> owner;
  const std::uint8_t* bytes = nullptr;
  std::size_t size = 0;
};

struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

FileBytes read_file(const fs::path& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) refuse(path, "is a directory, not a model base file");
  const FileDescriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) refuse(path, std::string("cannot open: ") + std::strerror(errno));
  struct stat status {};
  if (::fstat(file.fd, &status) != 0)
    refuse(path, std::string("cannot read its size: ") + std::strerror(errno));
  FileBytes out;
  out.size = static_cast<std::size_t>(status.st_size);
  if (out.size == 0) {
    static constexpr std::uint8_t kNothing[1] = {0};
    out.bytes = kNothing;
    return out;
  }
  void* address = ::mmap(nullptr, out.size, PROT_READ, MAP_PRIVATE, file.fd, 0);
  if (address == MAP_FAILED) refuse(path, std::string("cannot read: ") + std::strerror(errno));
  const std::size_t size = out.size;
  out.owner = std::shared_ptr<const void>(
      address, [size](const void* mapped) { ::munmap(const_cast<void*>(mapped), size); });
  out.bytes = static_cast<const std::uint8_t*>(address);
  return out;
}

Header check_header(const FileBytes& file, const fs::path& path) {
  const std::uint8_t* p = file.bytes;
  if (file.size < sizeof kMagic || std::memcmp(p, kMagic, sizeof kMagic) != 0) {
    if (file.size < sizeof kMagic && std::memcmp(p, kMagic, file.size) == 0)
      refuse(path, "truncated: " + std::to_string(file.size) + " bytes, shorter than the header");
    refuse(path, "not a COSMOS model base (no COSMOSMB magic at its start)");
  }
  if (file.size < kModelBaseHeaderBytes)
    refuse(path, "truncated: " + std::to_string(file.size) + " bytes, shorter than the " +
                     std::to_string(kModelBaseHeaderBytes) + "-byte header");
  Header header;
  header.format_version = static_cast<std::uint32_t>(get_le(p + 8, 4));
  header.header_bytes = static_cast<std::uint32_t>(get_le(p + 12, 4));
  header.payload_bytes = get_le(p + 16, 8);
  header.payload_checksum = get_le(p + 24, 8);
  if (header.format_version != ModelBase::kFormatVersion)
    refuse(path, "format version " + std::to_string(header.format_version) +
                     ", this build reads version " + std::to_string(ModelBase::kFormatVersion) +
                     " (rebuild it with `cosmos modelbase build`)");
  if (header.header_bytes != kModelBaseHeaderBytes)
    refuse(path, "corrupted: header size " + std::to_string(header.header_bytes) + ", expected " +
                     std::to_string(kModelBaseHeaderBytes));
  const std::uint64_t expected_size = kModelBaseHeaderBytes + header.payload_bytes;
  if (header.payload_bytes > kMaxPayloadBytes || file.size > expected_size)
    refuse(path, "corrupted: size mismatch (" + std::to_string(file.size) +
                     " bytes, the header announces " + std::to_string(expected_size) + ")");
  if (file.size < expected_size)
    refuse(path, "truncated: " + std::to_string(file.size) + " of " +
                     std::to_string(expected_size) + " bytes");
  return header;
}

}  // namespace

void write_model_base(const ModelBase& base, const fs::path& path) {
  const std::size_t estimate = estimated_payload_bytes(base);
  if (estimate > kMaxPayloadBytes)
    refuse(path, "model base too large for one file (~" + std::to_string(estimate >> 20) +
                     " MiB, at most 2048 MiB)");
  flatbuffers::FlatBufferBuilder builder(estimate);
  encode_model_base(base, builder);
  const std::uint8_t* payload = builder.GetBufferPointer();
  const std::size_t payload_bytes = builder.GetSize();

  unsigned char header[kModelBaseHeaderBytes];
  std::memcpy(header, kMagic, sizeof kMagic);
  put_le(header + 8, ModelBase::kFormatVersion, 4);
  put_le(header + 12, kModelBaseHeaderBytes, 4);
  put_le(header + 16, payload_bytes, 8);
  put_le(header + 24, xxh64(payload, payload_bytes), 8);

  fs::path temporary = path;
  temporary += ".tmp-" + std::to_string(::getpid());
  {
    const File file(std::fopen(temporary.c_str(), "wb"));
    if (!file) refuse(path, std::string("cannot write: ") + std::strerror(errno));
    write_all(file.get(), header, sizeof header, path);
    write_all(file.get(), payload, payload_bytes, path);
    if (std::fflush(file.get()) != 0)
      refuse(path, std::string("cannot write: ") + std::strerror(errno));
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    fs::remove(temporary, error);
    refuse(path, "cannot write: " + error.message());
  }
}

ModelBase read_model_base(const fs::path& path,
                          const std::optional<std::string>& expected_parameters_text) {
  const FileBytes file = read_file(path);
  const Header header = check_header(file, path);
  const std::uint8_t* payload = file.bytes + kModelBaseHeaderBytes;
  const std::uint64_t checksum = xxh64(payload, header.payload_bytes);
  if (checksum != header.payload_checksum)
    refuse(path, "corrupted: checksum mismatch (header " + hex(header.payload_checksum) +
                     ", payload " + hex(checksum) + ")");
  ModelBase base;
  if (auto reason = decode_model_base(payload, header.payload_bytes, file.owner, base))
    refuse(path, "corrupted: " + *reason);
  if (expected_parameters_text) {
    if (auto difference =
            first_parameter_difference(*expected_parameters_text, base.parameters_text))
      refuse(path, "built with other parameters: " + difference->key + " is " + difference->actual +
                       " in the file, " + difference->expected +
                       " expected (rebuild it with `cosmos modelbase build`)");
  }
  return base;
}

}  // namespace cosmos
