#include "connection.h"

#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>

namespace hexc::edit {

namespace {

thread_local bool closeAfter = false;  // a connection is served by one thread from its first request to its close

using Clock = std::chrono::steady_clock;

int millis(Clock::duration d) { return int(std::max<int64_t>(0, std::chrono::duration_cast<std::chrono::milliseconds>(d).count())); }

bool ready(int sock, short events, int timeoutMs) {
    pollfd p{sock, events, 0};
    return ::poll(&p, 1, timeoutMs) > 0 && (p.revents & (events | POLLHUP | POLLERR));
}

void address(int sock, bool remote, std::string& ip, int& port) {
    sockaddr_storage a{};
    socklen_t size = sizeof a;
    char host[NI_MAXHOST] = "", service[NI_MAXSERV] = "";
    if ((remote ? ::getpeername(sock, reinterpret_cast<sockaddr*>(&a), &size)
                : ::getsockname(sock, reinterpret_cast<sockaddr*>(&a), &size)) == 0 &&
        ::getnameinfo(reinterpret_cast<sockaddr*>(&a), size, host, sizeof host, service, sizeof service, NI_NUMERICHOST | NI_NUMERICSERV) ==
            0) {
        ip = host;
        port = std::atoi(service);
    }
}

// One connection's bytes, read ahead in blocks; while a request's head is being read, at most kMaxHeadBytes of it, all
// within kHeadTime: past either, a read fails, httplib answers 400 and the connection closes.
class HeadBoundedStream : public httplib::Stream {
public:
    HeadBoundedStream(int sock, Clock::duration readTimeout, Clock::duration writeTimeout)
        : sock_(sock), readTimeout_(readTimeout), writeTimeout_(writeTimeout) {}

    // The next request's head starts here.
    void nextRequest() {
        headBytes_ = 0;
        matched_ = 0;
        inHead_ = true;
        headEnd_ = Clock::now() + kHeadTime;
    }
    bool buffered() const { return at_ < end_; }

    bool is_readable() const override { return buffered() || ready(sock_, POLLIN, millis(readTimeout())); }
    // Whether the client is still there: writable, and not closed (a peek returns 0 once it has gone).
    bool is_writable() const override {
        if (!ready(sock_, POLLOUT, millis(writeTimeout_))) return false;
        char byte;
        return !ready(sock_, POLLIN, 0) || ::recv(sock_, &byte, 1, MSG_PEEK | MSG_DONTWAIT) > 0;
    }
    ssize_t read(char* ptr, size_t size) override {
        if (inHead_ && headBytes_ >= kMaxHeadBytes) return -1;
        if (!buffered()) {
            if (!is_readable()) return -1;
            const ssize_t n = ::recv(sock_, buffer_, sizeof buffer_, 0);
            if (n <= 0) return n;
            at_ = 0;
            end_ = size_t(n);
        }
        size_t n = std::min(size, end_ - at_);
        if (inHead_) n = headPart(std::min(n, kMaxHeadBytes - headBytes_));
        std::memcpy(ptr, buffer_ + at_, n);
        at_ += n;
        return ssize_t(n);
    }
    ssize_t write(const char* ptr, size_t size) override {
        if (!ready(sock_, POLLOUT, millis(writeTimeout_))) return -1;
        return ::send(sock_, ptr, size, MSG_NOSIGNAL);
    }
    void get_remote_ip_and_port(std::string& ip, int& port) const override { address(sock_, true, ip, port); }
    void get_local_ip_and_port(std::string& ip, int& port) const override { address(sock_, false, ip, port); }
    socket_t socket() const override { return sock_; }

private:
    // Within the head, a read ends where the blank line after the headers does, so that the body is not counted.
    size_t headPart(size_t n) {
        for (size_t i = 0; i < n; ++i) {
            const char c = buffer_[at_ + i];
            matched_ = c == '\r' ? (matched_ == 2 ? 3 : 1) : (c == '\n' && (matched_ == 1 || matched_ == 3)) ? matched_ + 1 : 0;
            if (matched_ == 4) {
                inHead_ = false;
                n = i + 1;
            }
        }
        headBytes_ += n;
        return n;
    }
    Clock::duration readTimeout() const { return inHead_ ? std::min(readTimeout_, headEnd_ - Clock::now()) : readTimeout_; }

    int sock_;
    Clock::duration readTimeout_, writeTimeout_;
    char buffer_[4096];
    size_t at_ = 0, end_ = 0;
    bool inHead_ = true;
    size_t headBytes_ = 0;
    int matched_ = 0;  // of "\r\n\r\n", the head's end
    Clock::time_point headEnd_;
};

// Waits for a connection's next request: false when the keep-alive time passes first or the server stops (`listening`
// becomes invalid), which it looks at now and then.
bool nextRequestArrives(const HeadBoundedStream& stream, int sock, std::chrono::seconds keepAlive, const std::atomic<socket_t>& listening) {
    const Clock::time_point end = Clock::now() + keepAlive;
    while (!stream.buffered() && !ready(sock, POLLIN, 100))
        if (Clock::now() >= end || listening == INVALID_SOCKET) return false;
    return true;
}

// Closes a connection whose request's body was left unread: stops writing, then reads and drops what the client sends
// until it closes, for at most `bytes` or `time`; then the close cannot reset the connection before the client read
// its answer (a close with unread input does).
void lingeringClose(int sock, size_t bytes, Clock::duration time) {
    ::shutdown(sock, SHUT_WR);
    const Clock::time_point end = Clock::now() + time;
    char dropped[16384];
    while (bytes > 0 && ready(sock, POLLIN, millis(end - Clock::now()))) {
        const ssize_t n = ::recv(sock, dropped, sizeof dropped, 0);
        if (n <= 0) return;
        bytes -= std::min(bytes, size_t(n));
    }
}

}  // namespace

void closeAfterAnswer() { closeAfter = true; }

// httplib's keep-alive loop (process_server_socket): requests until the client closes, the server stops, the connection
// has served its count or waited its keep-alive time for the next.
bool BoundedServer::process_and_close_socket(socket_t sock) {
    using std::chrono::microseconds, std::chrono::seconds;
    HeadBoundedStream stream(sock, seconds(read_timeout_sec_) + microseconds(read_timeout_usec_),
                             seconds(write_timeout_sec_) + microseconds(write_timeout_usec_));
    bool ok = false;
    closeAfter = false;
    for (size_t left = keep_alive_max_count_; left > 0 && nextRequestArrives(stream, sock, seconds(keep_alive_timeout_sec_), svr_sock_);
         --left) {
        stream.nextRequest();
        closeAfter = false;
        bool closed = false;
        ok = process_request(stream, left == 1, closed, nullptr);
        if (!ok || closed || closeAfter) break;
    }
    if (closeAfter) lingeringClose(sock, maxBody_, seconds(read_timeout_sec_) + microseconds(read_timeout_usec_));
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
    return ok;
}

}  // namespace hexc::edit
