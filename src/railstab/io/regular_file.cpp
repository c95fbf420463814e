#include <railstab/io/regular_file.hpp>

#include <filesystem>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace railstab {

namespace {

const char* file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a named pipe";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

struct FileDescriptor {
  int fd;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_regular_file(const std::string& path, std::size_t max_bytes) {
  // O_NONBLOCK: opening a FIFO for reading returns at once instead of
  // waiting for a writer. O_NOCTTY: a terminal never becomes ours.
  const FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (file.fd < 0)
    throw std::runtime_error(std::string("expected a readable file, got none (cannot open it: ") +
                             std::strerror(errno) + ")");
  struct stat st {};
  if (::fstat(file.fd, &st) != 0)
    throw std::runtime_error(std::string("cannot inspect the file: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    throw std::runtime_error(std::string("expected a regular file, got ") + file_kind(st.st_mode) +
                             " (not a regular file)");
  if (std::size_t(st.st_size) > max_bytes)
    throw std::runtime_error("expected a file of at most " + std::to_string(max_bytes) +
                             " bytes, got " + std::to_string(st.st_size) + " bytes");
  // Regular files never block; clear O_NONBLOCK anyway for plain reads.
  ::fcntl(file.fd, F_SETFL, ::fcntl(file.fd, F_GETFL) & ~O_NONBLOCK);
  std::string text;
  text.reserve(std::size_t(st.st_size));
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("error while reading: ") + std::strerror(errno));
    }
    text.append(buffer, std::size_t(n));
    if (text.size() > max_bytes)  // grew while being read
      throw std::runtime_error("expected a file of at most " + std::to_string(max_bytes) +
                               " bytes, got more");
  }
  return text;
}

std::string path_relative_to_file(const std::string& file_path, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute()) return p.lexically_normal().string();
  return (std::filesystem::path(file_path).parent_path() / p).lexically_normal().string();
}

}  // namespace railstab
