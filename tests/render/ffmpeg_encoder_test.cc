#include "dream/render/ffmpeg_encoder.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "temp_folder.h"
#include "video_probe.h"

namespace dream::render {
namespace {

using dream::testing::TempFolder;

// Runs `body` with PATH set to `path`, restoring it afterwards.
template <typename Body>
void WithPath(const std::string& path, Body body) {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", path.c_str(), 1);
  try {
    body();
  } catch (...) {
    ::setenv("PATH", saved.c_str(), 1);
    throw;
  }
  ::setenv("PATH", saved.c_str(), 1);
}

TEST(FfmpegEncoderTest, WithoutFfmpegSaysHowToInstallIt) {
  TempFolder empty;
  WithPath(empty / "", [&] {
    EXPECT_FALSE(FfmpegEncoder::IsInstalled());
    try {
      FfmpegEncoder encoder({64, 64, 10}, {"-f", "mp4", empty / "x.mp4"});
      FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("apt-get install ffmpeg"), std::string::npos) << e.what();
    }
  });
  EXPECT_TRUE(empty.Files().empty());
}

TEST(FfmpegEncoderTest, FailuresQuoteFfmpeg) {
  if (!testing::OnPath("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed";
  EXPECT_TRUE(FfmpegEncoder::IsInstalled());
  TempFolder dir;
  const std::vector<unsigned char> frame(64 * 64 * 4, 0x80);
  try {
    FfmpegEncoder encoder({64, 64, 10}, {"-c:v", "no_such_codec", "-f", "mp4", dir / "x.mp4"});
    for (int i = 0; i < 200; ++i) encoder.WriteFrame(frame.data(), 64 * 4);  // ffmpeg may be gone by now
    encoder.Finish();
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_codec"), std::string::npos) << e.what();
  }
}

TEST(FfmpegEncoderTest, EncodesEveryFrameAndRestoresSigpipe) {
  if (!testing::OnPath("ffmpeg") || !testing::OnPath("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
  TempFolder dir;
  struct sigaction before {};
  ::sigaction(SIGPIPE, nullptr, &before);
  {
    // Rows padded past the picture's width, as cairo may lay them out.
    const int width = 64;
    const int stride = width * 4 + 32;
    std::vector<unsigned char> frame(static_cast<size_t>(stride) * 48, 0);
    FfmpegEncoder encoder({width, 48, 25}, {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-f", "mp4", dir / "x.mp4"});
    for (int i = 0; i < 12; ++i) {
      frame[static_cast<size_t>(i) * 4] = 0xff;
      encoder.WriteFrame(frame.data(), stride);
    }
    encoder.Finish();
  }
  EXPECT_EQ(testing::CountVideoFrames(dir / "x.mp4"), 12);
  struct sigaction after {};
  ::sigaction(SIGPIPE, nullptr, &after);
  EXPECT_EQ(after.sa_handler, before.sa_handler);
}

}  // namespace
}  // namespace dream::render
