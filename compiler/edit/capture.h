#pragma once
// `hexc edit --capture OUT.png`: headless Chromium opens the page, which draws one frame with its default camera and
// posts the frame's texels back; they are written as a PNG and everything stops.
#include <filesystem>
#include <future>
#include <string>
#include <vector>

#include "server.h"

namespace hexc::edit {

struct CaptureOptions {
    std::filesystem::path out;
    int width = 1280, height = 720;
    std::string browser = "chromium";
    // Generous: a loaded two-core machine draws the first frame in software within seconds, but starts Chromium slowly.
    int timeoutSeconds = 300;
};

// The Chromium flags hexc edit (and its tests, tests/edit/browser.py) start a headless browser with: no sandbox (CI runs
// as root), no network of its own, WebGL 2 on SwiftShader (software), where there is no GPU.
std::vector<std::string> headlessChromiumFlags();

class Capture {
public:
    explicit Capture(CaptureOptions options) : options_(std::move(options)) {}
    // What the server calls with the page's frame: writes it, and ends run().
    Server::CaptureHandler handler();
    // Opens the page of `server` (already listening) in headless Chromium, serves it until the frame came or the time is
    // out, and returns the exit code.
    int run(Server& server);

private:
    int wait(int browser);  // the exit code once the frame came, the browser ended or the time is out

    CaptureOptions options_;
    std::promise<int> done_;
    std::once_flag once_;
};

}  // namespace hexc::edit
