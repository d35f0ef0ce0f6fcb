#pragma once
// The HTTP side of `hexc edit`: a server on 127.0.0.1 that answers only requests carrying its token, addressed to its
// own host name, for the page's own files and the session's routes; nothing maps a request path to a file.
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "session.h"

namespace hexc::edit {

// Bodies the page sends are a material (kilobytes) or, in capture mode, one frame's RGBA texels of at most
// kMaxCaptureSide^2 pixels; anything larger is refused unread (413).
constexpr int kMaxCaptureSide = 2048;
constexpr size_t kMaxRequestBytes = size_t(kMaxCaptureSide) * kMaxCaptureSide * 4 + 4096;
constexpr size_t kMaxDocumentBytes = 1 << 20;
constexpr size_t kWorkers = 32;  // connections served at once
// Change notifications (/api/events) hold a worker each while open: a few at once (a page opens one), each open for a
// while (the browser reconnects), looking at the files' stamps a few times a second.
constexpr int kEventStreams = 4;
constexpr std::chrono::seconds kEventStreamLife{15};
constexpr std::chrono::milliseconds kEventLook{150};

class Server {
public:
    // A frame the page captured (--capture): `body` holds its RGBA rows top first, or (failed) the page's diagnostics.
    using CaptureHandler = std::function<Reply(int width, int height, const std::string& body, bool failed)>;

    Server(Session& session, int port, CaptureHandler capture = {});
    ~Server();
    int port() const;                // the port it listens on (an unused one when asked for 0)
    const std::string& url() const;  // what to open: http://127.0.0.1:PORT/?token=...
    void run();                      // serves until stop()
    void stop();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace hexc::edit
