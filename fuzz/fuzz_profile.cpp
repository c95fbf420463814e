// libFuzzer harness: wheel and rail profile readers (src/railstab/profiles/).
//
// The first byte picks the reader (SIMPACK .prw wheel, .prr rail, plain text
// in mm or m); the rest is the file. Contract: a Profile, or a ProfileError
// whose message names the file; anything else (crash, sanitizer report,
// another exception type, a message without the file name) aborts.
// Seed corpus: cases/profiles/*.pr?.
#include <railstab/profiles/profile_readers.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

[[noreturn]] void finding(const char* what, const std::string& message) {
  std::fprintf(stderr, "FUZZ FINDING (%s): %s\n", what, message.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1 || size > 256 * 1024) return 0;
  using namespace railstab;
  const int mode = data[0] % 4;
  static const char* const kExtensions[] = {".prw", ".prr", ".txt", ".dat"};
  const std::string path = "/tmp/railstab_fuzz_profile_" + std::to_string(::getpid()) +
                           kExtensions[mode];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  const ProfileKind kind = mode == 1 || mode == 3 ? ProfileKind::rail : ProfileKind::wheel;
  const LengthUnit unit = mode == 2 ? LengthUnit::millimetre : LengthUnit::metre;
  try {
    const Profile profile = read_profile_file(path, kind, unit);
    (void)profile;
  } catch (const ProfileError& e) {
    const std::string message = e.what();
    if (message.find(path) == std::string::npos) finding("error does not name the file", message);
  } catch (const std::exception& e) {
    finding("profile reader threw a non-ProfileError", e.what());
  }
  std::remove(path.c_str());
  return 0;
}
