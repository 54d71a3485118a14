// posix_spawn, a pipe read with poll, and a kill when the time is up or the caller cancels.

#include "io/helper_process.h"

#include "core/huge_pages.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace raylab {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kHelperFd = 3;
constexpr int kPollMs = 20;

// Closes a descriptor when it goes out of scope.
struct Fd {
    int fd = -1;
    ~Fd() { reset(); }
    void reset() {
        if (fd >= 0) {
            ::close(fd);
        }
        fd = -1;
    }
};

// Spawn attributes and file actions, destroyed on scope exit.
struct SpawnSetup {
    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attr;
    SpawnSetup() {
        posix_spawn_file_actions_init(&actions);
        posix_spawnattr_init(&attr);
    }
    ~SpawnSetup() {
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attr);
    }
    SpawnSetup(const SpawnSetup&) = delete;
    SpawnSetup& operator=(const SpawnSetup&) = delete;
};

// The child's descriptors: /dev/null for 0, 1 and 2, `writeEnd` as 3, nothing else. Its signals:
// default dispositions and an empty mask, whatever the parent's threads had.
int prepare(SpawnSetup& s, int writeEnd) {
    int rc = posix_spawn_file_actions_addopen(&s.actions, 0, "/dev/null", O_RDONLY, 0);
    rc = rc ? rc : posix_spawn_file_actions_addopen(&s.actions, 1, "/dev/null", O_WRONLY, 0);
    rc = rc ? rc : posix_spawn_file_actions_addopen(&s.actions, 2, "/dev/null", O_WRONLY, 0);
    rc = rc ? rc : posix_spawn_file_actions_adddup2(&s.actions, writeEnd, kHelperFd);
    rc = rc ? rc : posix_spawn_file_actions_addclosefrom_np(&s.actions, kHelperFd + 1);
    sigset_t all, none;
    sigfillset(&all);
    sigemptyset(&none);
    rc = rc ? rc : posix_spawnattr_setsigdefault(&s.attr, &all);
    rc = rc ? rc : posix_spawnattr_setsigmask(&s.attr, &none);
    rc =
        rc ? rc : posix_spawnattr_setflags(&s.attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    return rc;
}

// Reads what is there without blocking; false at end of file or on an error. The buffer grows
// by up to 1 MiB a read, or takes the whole room once options.expectedBytes knows it (`sized`).
bool drain(int fd, std::vector<uint8_t>& data, const HelperOptions& options, bool& sized,
           bool& overCap) {
    const std::size_t maxBytes = options.maxBytes;
    constexpr std::size_t kPiece = std::size_t{1} << 20;
    for (;;) {
        if (!sized && options.expectedBytes) {
            if (const std::size_t total = options.expectedBytes(data.data(), data.size())) {
                // One byte more than the data: the read that finds the end of the file then
                // needs no room of its own, which would copy the whole buffer.
                data.reserve(std::min(total, maxBytes) + 1);
                adviseHugePages(data.data() + data.size(), data.capacity() - data.size());
                sized = true;
            }
        }
        const std::size_t old = data.size();
        const std::size_t room = data.capacity() - old;
        const std::size_t chunk = room > 0 ? std::min(room, kPiece) : kPiece;
        data.resize(old + chunk);
        const ssize_t n = ::read(fd, data.data() + old, chunk);
        data.resize(old + (n > 0 ? static_cast<std::size_t>(n) : 0));
        if (n > 0) {
            if (data.size() > maxBytes) {
                overCap = true;
                return false;
            }
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
            return true;
        }
        return false; // 0: end of file; an error ends the reading too
    }
}

// The parent's environment with `extra` ("NAME=VALUE") on top; the strings stay in `storage`.
std::vector<char*> environmentWith(const std::vector<std::string>& extra,
                                   std::vector<std::string>& storage) {
    storage.clear();
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string entry(*e);
        const std::string name = entry.substr(0, entry.find('='));
        const bool replaced = std::any_of(extra.begin(), extra.end(), [&](const std::string& x) {
            return x.compare(0, name.size() + 1, name + "=") == 0;
        });
        if (!replaced) {
            storage.push_back(entry);
        }
    }
    storage.insert(storage.end(), extra.begin(), extra.end());
    std::vector<char*> pointers;
    for (std::string& entry : storage) {
        pointers.push_back(entry.data());
    }
    pointers.push_back(nullptr);
    return pointers;
}

// Waits up to `ms` milliseconds for the child behind `pidfd` to end (its descriptor becomes
// readable then); without a pidfd, sleeps 2 ms.
void waitForExit(int pidfd, int ms) {
    if (pidfd < 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        return;
    }
    pollfd p{pidfd, POLLIN, 0};
    ::poll(&p, 1, ms);
}

} // namespace

HelperRun runHelper(const std::vector<std::string>& argv, const HelperOptions& options) {
    HelperRun run;
    Fd readEnd, writeEnd;
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) {
        run.error = std::string("cannot make a pipe: ") + std::strerror(errno);
        return run;
    }
    readEnd.fd = fds[0];
    writeEnd.fd = fds[1];
    if (writeEnd.fd == kHelperFd) { // dup2 onto itself would keep close-on-exec set
        const int moved = ::fcntl(writeEnd.fd, F_DUPFD_CLOEXEC, kHelperFd + 1);
        writeEnd.reset();
        writeEnd.fd = moved;
    }
    ::fcntl(readEnd.fd, F_SETFL, ::fcntl(readEnd.fd, F_GETFL) | O_NONBLOCK);
    ::fcntl(readEnd.fd, F_SETPIPE_SZ, 1 << 20); // fewer wake-ups for big meshes; best effort

    std::vector<char*> args;
    for (const std::string& a : argv) {
        args.push_back(const_cast<char*>(a.c_str()));
    }
    args.push_back(nullptr);
    std::vector<std::string> environmentStorage;
    const std::vector<char*> environment = environmentWith(options.environment, environmentStorage);
    SpawnSetup setup;
    pid_t pid = 0;
    int rc = prepare(setup, writeEnd.fd);
    if (rc == 0) {
        rc = ::posix_spawn(&pid, args[0], &setup.actions, &setup.attr, args.data(),
                           environment.data());
    }
    writeEnd.reset(); // only the child writes; its exit ends the reading
    if (rc != 0) {
        run.error = std::string("cannot start ") + argv[0] + ": " + std::strerror(rc);
        return run;
    }
    run.started = true;

    const auto start = Clock::now();
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(options.seconds));
    bool killed = false;
    const auto killChild = [&] {
        ::kill(pid, SIGKILL);
        killed = true;
    };
    bool open = true;
    bool sized = false;
    while (open && !killed) {
        pollfd p{readEnd.fd, POLLIN, 0};
        ::poll(&p, 1, kPollMs);
        open = drain(readEnd.fd, run.data, options, sized, run.overCap);
        const auto now = Clock::now();
        if (run.overCap) {
            killChild();
        } else if (open && now >= deadline) {
            run.timedOut = true;
            killChild();
        } else if (open && options.cancelled && options.cancelled()) {
            run.cancelled = true;
            killChild();
        } else if (options.running) {
            options.running(std::chrono::duration<double>(now - start).count());
        }
    }
    // The pipe is closed: the helper is ending (or could close it and linger, so the deadline
    // and cancel still hold while we wait).
    if (!killed && options.received) {
        options.received(run.data);
    }
    Fd pidfd;
    pidfd.fd = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
    int status = 0;
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, killed ? 0 : WNOHANG);
        if (done == pid || (done < 0 && errno != EINTR)) {
            break;
        }
        if (done == 0) {
            if (Clock::now() >= deadline) {
                run.timedOut = true;
                killChild();
            } else if (options.cancelled && options.cancelled()) {
                run.cancelled = true;
                killChild();
            } else {
                waitForExit(pidfd.fd, kPollMs);
            }
        }
    }
    if (WIFEXITED(status)) {
        run.exitCode = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        run.signal = WTERMSIG(status);
    }
    return run;
}

} // namespace raylab
