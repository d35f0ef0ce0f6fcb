#include "capture.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <thread>

#include "hexc/image.h"
#include "command.h"

extern char** environ;

namespace hexc::edit {

std::vector<std::string> headlessChromiumFlags() {
    return {"--headless",
            "--no-sandbox",  // as root, Chromium's sandbox does not start
            "--disable-gpu",
            "--enable-unsafe-swiftshader",  // WebGL on the software renderer, without the deprecation fallback
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars"};
}

namespace {

// Starts `argv` in a process group of its own, so that stopping it stops the renderer processes it starts too.
pid_t spawn(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
    // Chromium's own log (D-Bus, GPU stalls) says nothing about the material: the page reports what went wrong.
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&files, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = -1;
    const int failed = posix_spawnp(&pid, args[0], &files, &attributes, args.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
    return failed ? -1 : pid;
}

void stopGroup(pid_t pid) {
    kill(-pid, SIGTERM);
    for (int i = 0; i < 50; ++i) {                        // 5 s to end, then killed
        if (waitpid(pid, nullptr, WNOHANG) != 0) return;  // ended (or reaped already)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    kill(-pid, SIGKILL);
    waitpid(pid, nullptr, 0);
}

}  // namespace

Server::CaptureHandler Capture::handler() {
    return [this](int width, int height, const std::string& texels, bool failed) -> Reply {
        int code = command::kOk;
        if (failed) {
            std::cerr << "hexc: the page could not draw the material:\n" << texels << "\n";
            code = command::kInvalidInput;
        } else if (width != options_.width || height != options_.height || texels.size() != size_t(width) * size_t(height) * 4) {
            return {400, "expected " + std::to_string(options_.width) + "x" + std::to_string(options_.height) + " RGBA texels",
                    "text/plain"};
        } else {
            try {
                Texture frame{width, height, false, std::vector<uint8_t>(texels.begin(), texels.end()), {}};
                const std::filesystem::path dir = options_.out.has_parent_path() ? options_.out.parent_path() : ".";
                command::writeAtomically(dir, options_.out.filename().string(), pngBytes(frame));
                std::cerr << "hexc: wrote " << options_.out.string() << "\n";
            } catch (const std::exception& e) {
                std::cerr << "hexc: " << e.what() << "\n";
                code = command::kWriteFailed;
            }
        }
        std::call_once(once_, [&] { done_.set_value(code); });
        return {200, "{}"};
    };
}

int Capture::wait(int browser) {
    std::future<int> done = done_.get_future();
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(options_.timeoutSeconds);
    while (std::chrono::steady_clock::now() < deadline) {
        if (done.wait_for(std::chrono::milliseconds(200)) == std::future_status::ready) return done.get();
        if (waitpid(browser, nullptr, WNOHANG) == browser) {
            std::cerr << "hexc: " << options_.browser << " ended before the page drew a frame\n";
            return command::kWriteFailed;
        }
    }
    std::cerr << "hexc: no frame from the page after " << options_.timeoutSeconds << " s\n";
    return command::kWriteFailed;
}

int Capture::run(Server& server) {
    // The browser's profile in a folder mkdtemp makes: a name no one can guess or take first, readable by us alone.
    std::string folder = (std::filesystem::temp_directory_path() / "hexc-edit-XXXXXX").string();
    if (!::mkdtemp(folder.data())) {
        std::cerr << "hexc: cannot make a folder for the browser's profile in " << std::filesystem::temp_directory_path().string() << "\n";
        return command::kWriteFailed;
    }
    const std::filesystem::path profile = folder;
    std::vector<std::string> argv = {options_.browser};
    for (const std::string& f : headlessChromiumFlags()) argv.push_back(f);
    argv.push_back("--user-data-dir=" + profile.string());  // a fresh profile, removed after
    argv.push_back("--window-size=" + std::to_string(options_.width) + "," + std::to_string(options_.height));
    argv.push_back(server.url() + "&capture=" + std::to_string(options_.width) + "x" + std::to_string(options_.height));
    std::thread serving([&] { server.run(); });
    int code = command::kWriteFailed;
    const pid_t browser = spawn(argv);
    if (browser < 0) {
        std::cerr << "hexc: cannot start `" << options_.browser
                  << "` for --capture (Debian: apt-get install chromium; --browser names another)\n";
    } else {
        code = wait(browser);
        stopGroup(browser);
    }
    server.stop();
    serving.join();
    std::error_code ec;
    std::filesystem::remove_all(profile, ec);
    return code;
}

}  // namespace hexc::edit
