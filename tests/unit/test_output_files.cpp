// Output-folder plumbing: the folder lock (one holder at a time, released on destruction, a stale lock file
// taken over, a folder created for a run that wrote nothing removed again), atomic whole-file writes, and the
// UTF-8 check of input text against RFC 3629's table of well-formed sequences.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"
#include "io/formats/output_lock.h"
#include "io/formats/utf8_text.h"

using namespace hullopt;
namespace fs = std::filesystem;

namespace {
fs::path Fresh(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("hullopt_test_output_files_" + name);
  fs::remove_all(p);
  return p;
}
std::string Read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("a second lock on a folder is refused while the first is held, and granted after it is released") {
  const fs::path dir = Fresh("lock");
  fs::create_directories(dir);
  {
    io::OutputFolderLock first(dir.string(), "optimize");
    // flock(2) locks belong to an open file description, so a second open in the same process conflicts.
    try {
      io::OutputFolderLock second(dir.string(), "explore");
      FAIL("second lock granted");
    } catch (const io::InputError& e) {
      const std::string m = e.what();
      CHECK(m.find("in use by another hullopt process") != std::string::npos);
      CHECK(m.find("pid " + std::to_string(::getpid())) != std::string::npos);
      CHECK(m.find("hullopt optimize") != std::string::npos);
      CHECK(m.find("started 20") != std::string::npos);
    }
  }
  std::string stale = "unset";
  io::OutputFolderLock again(dir.string(), "explore", &stale);
  CHECK(stale.empty());  // released cleanly: nothing to take over
  fs::remove_all(dir);
}

TEST_CASE("a lock file naming a holder that no longer holds it is taken over as stale") {
  const fs::path dir = Fresh("stale");
  fs::create_directories(dir);
  std::ofstream(dir / io::OutputFolderLock::FileName()) << "pid 999999 on host gone, hullopt optimize, started x\n";
  std::string stale;
  io::OutputFolderLock lock(dir.string(), "optimize", &stale);
  CHECK(stale == "pid 999999 on host gone, hullopt optimize, started x");
  CHECK(Read(dir / io::OutputFolderLock::FileName()).find("pid " + std::to_string(::getpid())) == 0);
  fs::remove_all(dir);
}

TEST_CASE("a folder the lock created is removed again if the run wrote nothing into it") {
  const fs::path unused = Fresh("unused"), used = Fresh("used");
  { io::OutputFolderLock lock(unused.string(), "rao"); }
  CHECK_FALSE(fs::exists(unused));
  {
    io::OutputFolderLock lock(used.string(), "rao");
    io::WriteFileAtomically((used / "rao.csv").string(), "x\n");
  }
  CHECK(fs::exists(used / "rao.csv"));
  CHECK(Read(used / io::OutputFolderLock::FileName()).empty());  // released: no holder named
  fs::remove_all(used);
}

TEST_CASE("atomic writes replace the whole file and leave no temporary behind") {
  const fs::path dir = Fresh("atomic");
  fs::create_directories(dir);
  const std::string path = (dir / "summary.json").string();
  io::WriteFileAtomically(path, "first version, longer than the second\n");
  io::WriteFileAtomically(path, std::string("bin\0ary\n", 8));
  CHECK(Read(path) == std::string("bin\0ary\n", 8));
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
  CHECK(files == 1);
  CHECK_THROWS_AS(io::WriteFileAtomically((dir / "missing" / "x.json").string(), "x"), io::InputError);
  fs::remove_all(dir);
}

TEST_CASE("UTF-8 validity follows RFC 3629 table 3") {
  std::size_t at = 99;
  CHECK(io::IsValidUtf8("plain ASCII"));
  CHECK(io::IsValidUtf8("Fn \xCE\xBB/L \xE2\x89\xA5 \xF0\x9F\x9A\xA2"));  // λ, ≥, ship emoji
  CHECK(io::IsValidUtf8("\xF4\x8F\xBF\xBF"));                               // U+10FFFF, the last code point
  CHECK_FALSE(io::IsValidUtf8("ab\xFF", &at));
  CHECK(at == 2);
  CHECK_FALSE(io::IsValidUtf8("\xC0\xAF"));          // overlong '/'
  CHECK_FALSE(io::IsValidUtf8("\xE0\x80\xAF"));      // overlong '/'
  CHECK_FALSE(io::IsValidUtf8("\xED\xA0\x80"));      // surrogate U+D800
  CHECK_FALSE(io::IsValidUtf8("\xF4\x90\x80\x80"));  // above U+10FFFF
  CHECK_FALSE(io::IsValidUtf8("x\xE2\x89", &at));    // truncated sequence at the end
  CHECK(at == 1);
  CHECK_FALSE(io::IsValidUtf8("\x80"));  // lone continuation byte
  try {
    io::RequireUtf8("name: a\nname: b\xE9t\n", "c.yaml");
    FAIL("accepted");
  } catch (const io::InputError& e) {
    CHECK(std::string(e.what()).find("c.yaml:2: invalid UTF-8 (byte 0xE9 at byte column 8)") == 0);
  }
}
