// naga in Node.js, where hexc has no naga built in (naga_wasm.cpp) or HEXC_NAGA=node asks for it. One Node.js
// process runs naga.mjs (embedded) for the whole run, over a socket pair: a socket, unlike a pipe, can be
// written with MSG_NOSIGNAL, so a Node that has gone away is an error here, not a SIGPIPE that ends hexc. Whatever runs
// as `node` is not trusted to answer: each answer has a time bound and its frame a size bound, and a process that
// breaks either is killed and reaped, so hexc neither hangs nor allocates what a frame merely claims.
#include "backends/naga.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>

#include <nlohmann/json.hpp>

#include "hexc/hash.h"
#include "hexc/templates.h"

extern char** environ;

namespace hexc {
namespace {

constexpr const char* kInstall =
    "the wgsl target needs naga built into hexc, or Node.js (`node` on PATH; Debian: apt-get install nodejs) and the npm "
    "package naga-wasm 30.1.0 (npm install naga-wasm@30.1.0 in a folder, then HEXC_NODE_PATH=<that folder>/node_modules; "
    "docs/cli.md, \"WGSL\")";

// The longest answer naga.mjs writes: WGSL of a shader is tens of kilobytes, naga's messages shorter.
constexpr uint32_t kMaxFrame = 64u << 20;

// How long one answer may take (docs/cli.md, "WGSL"): Node's start with naga-wasm's load takes about a second and a
// translation well under one; HEXC_NODE_TIMEOUT (seconds, 1 to 3600) for a machine far slower than that.
std::chrono::seconds answerTimeout() {
    const char* set = std::getenv("HEXC_NODE_TIMEOUT");
    const long seconds = set ? std::strtol(set, nullptr, 10) : 0;
    return std::chrono::seconds(seconds >= 1 && seconds <= 3600 ? seconds : 60);
}

class NagaProcess {
public:
    NagaProcess() {
        int sockets[2];
        if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) {
            error_ = std::string("cannot start Node.js: ") + std::strerror(errno);
            return;
        }
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, sockets[1], 0);
        posix_spawn_file_actions_adddup2(&actions, sockets[1], 1);
        posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);  // Node's warnings; errors come as frames
        const std::string& script = *embeddedText("naga.mjs");
        char* argv[] = {const_cast<char*>("node"), const_cast<char*>("--input-type=module"), const_cast<char*>("-e"),
                        const_cast<char*>(script.c_str()), nullptr};
        const int spawned = posix_spawnp(&pid_, "node", &actions, nullptr, argv, environ);
        posix_spawn_file_actions_destroy(&actions);
        close(sockets[1]);
        socket_ = sockets[0];
        if (spawned != 0) {
            pid_ = -1;
            error_ = std::string("cannot run `node`: ") + std::strerror(spawned) + "; " + kInstall;
            return;
        }
        bool ok = false;
        std::string hello;
        if (std::string why = receive(ok, hello, deadline()); !why.empty())
            fail("`node` did not start the translator: " + why);
        else if (!ok)
            error_ = hello + "; " + kInstall;
    }
    ~NagaProcess() { stop(); }  // every answer asked for has come: nothing is lost by killing it
    NagaResult translate(const std::vector<uint32_t>& spirv) {
        if (!error_.empty()) return {std::nullopt, error_, true};
        const uint32_t size = uint32_t(spirv.size() * 4);
        bool ok = false;
        std::string text;
        const Deadline by = deadline();  // for the request and its answer
        std::string why = transfer(&size, 4, true, by);
        if (why.empty()) why = transfer(spirv.data(), size, true, by);
        if (why.empty()) why = receive(ok, text, by);
        if (!why.empty()) {
            fail("the Node.js process running naga failed: " + why);
            return {std::nullopt, error_, true};
        }
        if (!ok) return {std::nullopt, text, false};
        return {text, "", false};
    }

private:
    using Deadline = std::chrono::steady_clock::time_point;
    static Deadline deadline() { return std::chrono::steady_clock::now() + answerTimeout(); }

    // Sends (`out`) or receives `size` bytes before `by`: "" when done, else why not. Each waits in poll(), so a
    // process that neither reads nor writes costs the time bound, never a hang.
    std::string transfer(const void* data, size_t size, bool out, Deadline by) {
        for (char* p = static_cast<char*>(const_cast<void*>(data)); size > 0;) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(by - std::chrono::steady_clock::now());
            pollfd wait{socket_, short(out ? POLLOUT : POLLIN), 0};
            const int ready = left.count() > 0 ? poll(&wait, 1, int(left.count())) : 0;
            if (ready < 0 && errno == EINTR) continue;
            if (ready == 0)
                return std::string(out ? "it read nothing" : "no answer") + " within " + std::to_string(answerTimeout().count()) +
                       " s (HEXC_NODE_TIMEOUT)";
            const ssize_t n = ready < 0 ? -1
                              : out     ? send(socket_, p, size, MSG_NOSIGNAL | MSG_DONTWAIT)
                                        : recv(socket_, p, size, MSG_DONTWAIT);
            if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
            if (n <= 0) return out ? "it stopped reading" : "it stopped mid-answer";
            p += n, size -= size_t(n);
        }
        return "";
    }
    // One answer frame (naga.mjs): a status byte, "o" or "e", and a length of at most kMaxFrame, checked before
    // anything is allocated for it. "" when it came whole, else why not.
    std::string receive(bool& ok, std::string& text, Deadline by) {
        char head[5];
        if (std::string why = transfer(head, 5, false, by); !why.empty()) return why;
        uint32_t size;
        std::memcpy(&size, head + 1, 4);
        if (head[0] != 'o' && head[0] != 'e') return "its answer is not a translator's frame";
        if (size > kMaxFrame)
            return "its answer claims " + std::to_string(size) + " bytes, more than the " + std::to_string(kMaxFrame >> 20) +
                   " MiB an answer may have";
        ok = head[0] == 'o';
        text.resize(size);
        return transfer(text.data(), size, false, by);
    }
    // The process broke the protocol or its time: later translations fail at once with `why`.
    void fail(const std::string& why) {
        stop();
        error_ = why + "; " + kInstall;
    }
    void stop() {
        if (socket_ >= 0) close(socket_), socket_ = -1;
        if (pid_ <= 0) return;
        kill(pid_, SIGKILL);
        while (waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
        }
        pid_ = -1;
    }

    pid_t pid_ = -1;
    int socket_ = -1;
    std::string error_;
};

}  // namespace

namespace {

// Built in, unless HEXC_NAGA=node asks for Node's (docs/cli.md, "WGSL").
bool inProcess() {
#ifdef HEXC_NAGA_BUILT_IN
    const char* route = std::getenv("HEXC_NAGA");
    return !route || std::string(route) != "node";
#else
    return false;
#endif
}

}  // namespace

std::string nagaVersion() {
#ifdef HEXC_NAGA_BUILT_IN
    if (inProcess()) return "naga-wasm " HEXC_NAGA_BUILT_IN;
#endif
    // Where naga.mjs imports it from: HEXC_NODE_PATH, or the working folder when that is unset.
    const char* folder = std::getenv("HEXC_NODE_PATH");
    std::ifstream in(std::filesystem::path(folder ? folder : "") / "naga-wasm" / "package.json");
    const nlohmann::json package = nlohmann::json::parse(in, nullptr, false);
    const bool found = package.is_object() && package.contains("version") && package["version"].is_string();
    return "naga-wasm " + (found ? package["version"].get<std::string>() : std::string("(not found)"));
}

std::string nagaBuild() {
#ifdef HEXC_NAGA_BUILT_IN
    return "naga-wasm " HEXC_NAGA_BUILT_IN " built in (HEXC_NAGA=node: Node.js's)";
#else
    return "naga in Node.js (npm naga-wasm at HEXC_NODE_PATH)";
#endif
}

std::string nagaIdentity() {
#ifdef HEXC_NAGA_BUILT_IN
    if (inProcess()) return nagaVersion() + ", built in " HEXC_NAGA_HASH;
#endif
    ContentHash driver;
    driver.add(*embeddedText("naga.mjs"));
    return nagaVersion() + ", driver " + driver.hex();
}

NagaResult nagaWgsl(const std::vector<uint32_t>& spirv) {
    if (inProcess()) return nagaWasmWgsl(spirv);
    static std::mutex mutex;
    std::lock_guard lock(mutex);
    static NagaProcess process;  // started on the first translation, ended with hexc
    return process.translate(spirv);
}

}  // namespace hexc
