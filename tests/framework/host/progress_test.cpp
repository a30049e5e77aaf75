// The progress display: one line per outer step off a terminal, nested steps shown as details,
// log lines never glued to the live line, and the events a listener (Python) receives.
#include "framework/host/progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/host/log.h"

namespace voroseal {
namespace {

// What was written to a temporary FILE.
std::string text_of(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string text;
  char buffer[4096];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
  return text;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  for (size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(text.substr(start, end - start));
  return lines;
}

TEST(Progress, LinesGiveOneLinePerOuterStepWithItsTime) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    Progress progress(ProgressDisplay::Lines, f);
    progress.start("remesh: clean-up");
    for (int phase = 0; phase < 5; ++phase) {
      progress.start("phase " + std::to_string(phase), 10);
      for (int k = 0; k < 10; ++k) progress.advance();
      progress.finish("ignored: nested");
    }
    progress.finish("22 phases");
    progress.start("tetmesh: TetGen");
    progress.finish();
  }
  const std::vector<std::string> lines = lines_of(text_of(f));
  std::fclose(f);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("remesh: clean-up: 22 phases (", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(" s)"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[1].rfind("tetmesh: TetGen (", 0), 0u) << lines[1];
}

TEST(Progress, OffWritesNothing) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    Progress progress(ProgressDisplay::Off, f);
    progress.start("a", 3);
    progress.advance();
    progress.finish();
  }
  EXPECT_EQ(text_of(f), "");
  std::fclose(f);
}

// On a terminal every log line starts on a cleared line and ends with a newline: the live line
// is redrawn after it, never glued to it.
TEST(Progress, LogLinesAreNeverGluedToTheLiveLine) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    Progress progress(ProgressDisplay::Terminal, f);
    Logger log(LogLevel::Info, f);
    log.attach(&progress);
    progress.start("remesh: optimising seeds", 100);
    progress.set(40);
    log.warning("something to say");
    progress.set(90);
    progress.finish();
  }
  const std::string text = text_of(f);
  std::fclose(f);
  const size_t at = text.find("warning: something to say\n");
  ASSERT_NE(at, std::string::npos) << text;
  ASSERT_GE(at, 4u);
  EXPECT_EQ(text.substr(at - 4, 4), "\r\033[K") << "the live line was not cleared first";
  // The live line after the message shows the step again, and the final line ends the output.
  EXPECT_NE(text.find("remesh: optimising seeds", at), std::string::npos);
  const std::vector<std::string> lines = lines_of(text);
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines.back().find("remesh: optimising seeds ("), std::string::npos) << lines.back();
  EXPECT_EQ(text.back(), '\n');
}

TEST(Progress, ListenerSeesNestedStepsAsDetails) {
  std::vector<ProgressEvent> events;
  Progress progress;
  progress.set_listener([&](const ProgressEvent& e) { events.push_back(e); });
  progress.start("remesh: clean-up");
  progress.start("shape: angles", 4);
  progress.advance(2);
  progress.advance(2);
  progress.finish();
  progress.finish();
  ASSERT_EQ(events.size(), 6u);
  EXPECT_EQ(events[0].step, "remesh: clean-up");
  EXPECT_EQ(events[0].detail, "");
  EXPECT_EQ(events[1].step, "remesh: clean-up");
  EXPECT_EQ(events[1].detail, "shape: angles");
  EXPECT_EQ(events[1].total, 4);
  EXPECT_EQ(events[3].done, 4);
  EXPECT_TRUE(events[4].finished);
  EXPECT_EQ(events[4].detail, "shape: angles");
  EXPECT_TRUE(events[5].finished);
  EXPECT_EQ(events[5].step, "remesh: clean-up");
  EXPECT_EQ(events[5].detail, "");
  EXPECT_GE(events[5].seconds, events[4].seconds);
}

// A step an exception leaves is abandoned: the next step is an outer one with its own line.
TEST(Progress, StepLeftByAnExceptionDoesNotSwallowTheNext) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    Progress progress(ProgressDisplay::Lines, f);
    try {
      ProgressStep step(progress, "read");
      throw std::runtime_error("unreadable");
    } catch (const std::runtime_error&) {
    }
    ProgressStep next(progress, "remesh: seed sampling");
    next.finish();
  }
  const std::vector<std::string> lines = lines_of(text_of(f));
  std::fclose(f);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("remesh: seed sampling (", 0), 0u) << lines[0];
}

}  // namespace
}  // namespace voroseal
