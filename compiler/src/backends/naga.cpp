// One Node.js process runs naga.mjs (embedded) for the whole run, over a socket pair: a socket, unlike a pipe, can be
// written with MSG_NOSIGNAL, so a Node that has gone away is an error here, not a SIGPIPE that ends hexc.
#include "backends/naga.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

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
    "the wgsl target needs Node.js (`node` on PATH; Debian: apt-get install nodejs) and the npm package naga-wasm 30.1.0 "
    "(npm install naga-wasm@30.1.0 in a folder, then HEXC_NODE_PATH=<that folder>/node_modules; docs/cli.md, \"WGSL\")";

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
        if (!receive(ok, hello))
            error_ = std::string("`node` did not start the translator; ") + kInstall;
        else if (!ok)
            error_ = hello + "; " + kInstall;
    }
    ~NagaProcess() {
        if (socket_ >= 0) close(socket_);  // the driver's stdin ends: it exits
        if (pid_ > 0) waitpid(pid_, nullptr, 0);
    }
    NagaResult translate(const std::vector<uint32_t>& spirv) {
        if (!error_.empty()) return {std::nullopt, error_, true};
        const uint32_t size = uint32_t(spirv.size() * 4);
        bool ok = false;
        std::string text;
        if (!sendAll(&size, 4) || !sendAll(spirv.data(), size) || !receive(ok, text))
            return {std::nullopt, std::string("the Node.js process running naga stopped; ") + kInstall, true};
        if (!ok) return {std::nullopt, text, false};
        return {text, "", false};
    }

private:
    bool sendAll(const void* data, size_t size) {
        for (const char* p = static_cast<const char*>(data); size > 0;) {
            const ssize_t n = send(socket_, p, size, MSG_NOSIGNAL);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            p += n, size -= size_t(n);
        }
        return true;
    }
    bool receiveAll(void* data, size_t size) {
        for (char* p = static_cast<char*>(data); size > 0;) {
            const ssize_t n = recv(socket_, p, size, 0);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            p += n, size -= size_t(n);
        }
        return true;
    }
    bool receive(bool& ok, std::string& text) {
        char head[5];
        if (!receiveAll(head, 5)) return false;
        uint32_t size;
        std::memcpy(&size, head + 1, 4);
        text.resize(size);
        ok = head[0] == 'o';
        return receiveAll(text.data(), size);
    }

    pid_t pid_ = -1;
    int socket_ = -1;
    std::string error_;
};

}  // namespace

std::string nagaVersion() {
    // Where naga.mjs imports it from: HEXC_NODE_PATH, or the working folder when that is unset.
    const char* folder = std::getenv("HEXC_NODE_PATH");
    std::ifstream in(std::filesystem::path(folder ? folder : "") / "naga-wasm" / "package.json");
    const nlohmann::json package = nlohmann::json::parse(in, nullptr, false);
    const bool found = package.is_object() && package.contains("version") && package["version"].is_string();
    return "naga-wasm " + (found ? package["version"].get<std::string>() : std::string("(not found)"));
}

std::string nagaIdentity() {
    ContentHash driver;
    driver.add(*embeddedText("naga.mjs"));
    return nagaVersion() + ", driver " + driver.hex();
}

NagaResult nagaWgsl(const std::vector<uint32_t>& spirv) {
    static std::mutex mutex;
    std::lock_guard lock(mutex);
    static NagaProcess process;  // started on the first translation, ended with hexc
    return process.translate(spirv);
}

}  // namespace hexc
