// The raster process (render/src/raster_process.cpp) and the renderer on top of it: what happens when
// it dies, hangs or is closed, and what it inherits.
#include "raster_process.h"

#include <dirent.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "softtune/render/palette.h"
#include "softtune/render/renderer.h"
#include "softtune/support/sanitizer_build.h"

namespace softtune::render {
namespace {

constexpr ImageSize kSize{32, 18};
constexpr Rgba kFill{200, 90, 30, 255};

// One opaque triangle over the left half, in the probed body's fill colour.
std::vector<Vertex> left_half() {
  const Rgba c = kFill;
  return {{0.0f, 0.0f, c}, {16.0f, 0.0f, c}, {0.0f, 18.0f, c}, {16.0f, 0.0f, c}, {16.0f, 18.0f, c}, {0.0f, 18.0f, c}};
}

Rgba pixel(const std::vector<std::uint8_t>& rgba, int x, int y) {
  const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * kSize.width + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

std::vector<std::uint8_t> buffer() { return std::vector<std::uint8_t>(kSize.width * kSize.height * 4); }

// Whether `pid` has ended (gone, or a zombie nobody has reaped yet).
bool ended(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;
  const auto close_paren = line.rfind(')');
  return close_paren == std::string::npos || line.compare(close_paren, 3, ") Z") == 0;
}

// This process's children that have not ended (every thread's), from /proc.
std::vector<pid_t> children() {
  std::vector<pid_t> pids;
  DIR* tasks = opendir("/proc/self/task");
  if (!tasks) return pids;
  while (const dirent* t = readdir(tasks)) {
    if (t->d_name[0] == '.') continue;
    std::ifstream in(std::string("/proc/self/task/") + t->d_name + "/children");
    for (pid_t pid; in >> pid;) {
      if (!ended(pid)) pids.push_back(pid);
    }
  }
  closedir(tasks);
  return pids;
}

TEST(RasterProcess, DrawsTheTrianglesAndExitsCleanlyWhenClosed) {
  RasterProcess p({});
  auto rgba = buffer();
  ASSERT_NO_THROW(p.rasterize(left_half(), kSize, rgba));
  EXPECT_TRUE(pixel(rgba, 4, 9) == kFill);
  EXPECT_TRUE(pixel(rgba, 28, 9) == palette::kBackground);
  // A sanitizer build reports leaks and errors through the exit status: it must be a plain 0.
  const int status = p.close_and_wait();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

TEST(RasterProcess, InheritsOnlyStdioAndItsSocket) {
  int leaked[2];
  ASSERT_EQ(pipe(leaked), 0);  // no close-on-exec: a careless spawn would hand these to the child
  RasterProcess p({});
  auto rgba = buffer();  // after a frame: the loader and Mesa have closed what they opened to start
  ASSERT_NO_THROW(p.rasterize(left_half(), kSize, rgba));
  std::set<std::string> fds;
  DIR* dir = opendir(("/proc/" + std::to_string(p.pid()) + "/fd").c_str());
  ASSERT_NE(dir, nullptr);
  while (const dirent* e = readdir(dir)) {
    if (e->d_name[0] != '.') fds.insert(e->d_name);
  }
  closedir(dir);
  close(leaked[0]);
  close(leaked[1]);
  std::string listed;
  for (const std::string& fd : fds) listed += fd + " ";
  EXPECT_EQ(fds, (std::set<std::string>{"0", "1", "2", "3"})) << listed;
}

TEST(RasterProcess, ADeadProcessFailsTheFrameSayingHowItEnded) {
  RasterProcess p({});
  auto rgba = buffer();
  ASSERT_NO_THROW(p.rasterize(left_half(), kSize, rgba));
  // SIGKILL, because a sanitizer build catches SIGSEGV and turns it into a report and an exit status.
  ASSERT_EQ(kill(p.pid(), SIGKILL), 0);
  try {
    p.rasterize(left_half(), kSize, rgba);
    ADD_FAILURE() << "a dead raster process drew a frame";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("killed by signal 9"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(p.alive());
}

TEST(RasterProcess, AHungFrameIsKilledAtTheTimeout) {
  RasterProcess p({.frame_timeout_ms = 300});
  auto rgba = buffer();
  ASSERT_NO_THROW(p.rasterize(left_half(), kSize, rgba));
  const pid_t pid = p.pid();
  ASSERT_EQ(kill(pid, SIGSTOP), 0);  // as if a frame never finished
  EXPECT_THROW(p.rasterize(left_half(), kSize, rgba), std::runtime_error);
  EXPECT_FALSE(p.alive());
  EXPECT_NE(kill(pid, 0), 0);  // killed and reaped
}

// The renderer on top: destroying it (as an idle pipeline worker does) ends and reaps its process; a
// crash costs one frame.
TEST(ProcessRenderer, DestroyingItEndsItsProcess) {
  auto r = make_osmesa_renderer();
  std::vector<std::uint8_t> rgba(640 * 360 * 4);
  r->render(DrawFrame{}, Camera{}, {640, 360}, rgba);
  const auto live = children();
  ASSERT_EQ(live.size(), 1u);
  r.reset();
  EXPECT_TRUE(ended(live[0]));
  EXPECT_TRUE(children().empty());
}

TEST(ProcessRenderer, AfterACrashOneFrameFailsAndTheNextIsDrawn) {
  auto r = make_osmesa_renderer();
  std::vector<std::uint8_t> rgba(640 * 360 * 4);
  r->render(DrawFrame{}, Camera{}, {640, 360}, rgba);
  const auto live = children();
  ASSERT_EQ(live.size(), 1u);
  ASSERT_EQ(kill(live[0], SIGKILL), 0);
  EXPECT_THROW(r->render(DrawFrame{}, Camera{}, {640, 360}, rgba), std::runtime_error);
  std::fill(rgba.begin(), rgba.end(), 0);
  EXPECT_NO_THROW(r->render(DrawFrame{}, Camera{}, {640, 360}, rgba));
  EXPECT_EQ(rgba[3], 255);  // drawn: opaque background
}

double raster_test_children_cpu() {
  rusage u{};
  ::getrusage(RUSAGE_CHILDREN, &u);
  return u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec;
}

// The raster process's CPU time as read from /proc (what the frame pipeline charges a preview) agrees with
// what the kernel reports for it once it is reaped (getrusage RUSAGE_CHILDREN), within its 10 ms ticks and
// its exit; the renderer sums it over frames.
TEST(RasterProcess, CpuTimeIsTheProcesssOwn) {
  const double before = raster_test_children_cpu();
  double last = 0.0;
  {
    RasterProcess p({});
    std::vector<std::uint8_t> rgba(1280 * 720 * 4);
    for (int i = 0; i < 30; ++i) ASSERT_NO_THROW(p.rasterize(left_half(), {1280, 720}, rgba));
    last = p.cpu_seconds();
    EXPECT_EQ(p.close_and_wait(), 0);
    EXPECT_EQ(p.cpu_seconds(), 0.0);  // no process
  }
  const double reaped = raster_test_children_cpu() - before;
  EXPECT_GT(last, 0.0);
  EXPECT_LE(last, reaped + 0.02);
  // What the process spends after the last frame: its exit, which in a sanitizer build includes the leak
  // check's scan of the heap (0.05 s more under ASan than the read after the last frame).
  const double exit_cpu = SOFTTUNE_SANITIZED_BUILD ? 0.25 : 0.05;
  EXPECT_GE(last, reaped - exit_cpu) << "reaped " << reaped << " s, read " << last << " s";

  auto r = make_osmesa_renderer();
  std::vector<std::uint8_t> frame(1280 * 720 * 4);
  EXPECT_EQ(r->raster_cpu_seconds(), 0.0);
  for (int i = 0; i < 10; ++i) r->render(DrawFrame{}, Camera{}, {1280, 720}, frame);
  EXPECT_GT(r->raster_cpu_seconds(), 0.0);
}

}  // namespace
}  // namespace softtune::render
