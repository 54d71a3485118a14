// The filter is an allowlist (anything else kills the process) with explicit kill rules in front
// for what must never happen. Builds with a sanitizer keep the kill rules but allow the rest,
// because their runtimes need system calls no importer makes; they are test builds.

#include "sandbox.h"

#include "io/sanitizer_build.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <seccomp.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

namespace raylab::import {

namespace {

bool setLimit(int resource, rlim_t value) {
    const rlimit limit{value, value};
    return ::setrlimit(resource, &limit) == 0;
}

// Owns a libseccomp context.
struct Filter {
    scmp_filter_ctx ctx;
    explicit Filter(uint32_t defaultAction) : ctx(seccomp_init(defaultAction)) {}
    ~Filter() { seccomp_release(ctx); }
    Filter(const Filter&) = delete;
    Filter& operator=(const Filter&) = delete;
};

// Flags that make an open write, create or truncate.
constexpr uint64_t kWriteFlags = O_WRONLY | O_RDWR | O_CREAT | O_TRUNC | O_APPEND | __O_TMPFILE;

// libseccomp refuses a rule whose action is the default action (-EACCES), so in the strict
// filter (default: kill) only the allow rules are added, in the lenient one (default: allow)
// only the kill rules.
int addRules(scmp_filter_ctx ctx, bool strict) {
    int rc = 0;
    const auto rule = [&](uint32_t action, int syscall, unsigned count,
                          scmp_arg_cmp cmp = scmp_arg_cmp{}) {
        if (rc != 0 || (action == SCMP_ACT_ALLOW) != strict) {
            return;
        }
        rc = count == 0 ? seccomp_rule_add(ctx, action, syscall, 0)
                        : seccomp_rule_add(ctx, action, syscall, 1, cmp);
    };
    const auto allow = [&](int syscall) { rule(SCMP_ACT_ALLOW, syscall, 0); };
    const auto kill = [&](int syscall) { rule(SCMP_ACT_KILL_PROCESS, syscall, 0); };
    // Never: the network, new programs, new processes, other processes, changing files.
    for (const int s :
         {SCMP_SYS(socket),    SCMP_SYS(socketpair), SCMP_SYS(connect),  SCMP_SYS(bind),
          SCMP_SYS(listen),    SCMP_SYS(accept),     SCMP_SYS(accept4),  SCMP_SYS(sendto),
          SCMP_SYS(sendmsg),   SCMP_SYS(recvfrom),   SCMP_SYS(execve),   SCMP_SYS(execveat),
          SCMP_SYS(fork),      SCMP_SYS(vfork),      SCMP_SYS(creat),    SCMP_SYS(unlink),
          SCMP_SYS(unlinkat),  SCMP_SYS(rename),     SCMP_SYS(renameat), SCMP_SYS(renameat2),
          SCMP_SYS(mkdir),     SCMP_SYS(mkdirat),    SCMP_SYS(rmdir),    SCMP_SYS(truncate),
          SCMP_SYS(ftruncate), SCMP_SYS(link),       SCMP_SYS(linkat),   SCMP_SYS(symlink),
          SCMP_SYS(symlinkat), SCMP_SYS(chmod),      SCMP_SYS(fchmodat), SCMP_SYS(chown),
          SCMP_SYS(fchownat),  SCMP_SYS(kill)}) {
        kill(s);
    }
    // Opening: read-only only. (open and openat: flags are the second and third argument.)
    rule(SCMP_ACT_ALLOW, SCMP_SYS(openat), 1, SCMP_A2(SCMP_CMP_MASKED_EQ, kWriteFlags, 0));
    rule(SCMP_ACT_ALLOW, SCMP_SYS(open), 1, SCMP_A1(SCMP_CMP_MASKED_EQ, kWriteFlags, 0));
    for (const uint64_t flag : {uint64_t{O_WRONLY}, uint64_t{O_RDWR}, uint64_t{O_CREAT},
                                uint64_t{O_TRUNC}, uint64_t{O_APPEND}, uint64_t{__O_TMPFILE}}) {
        rule(SCMP_ACT_KILL_PROCESS, SCMP_SYS(openat), 1, SCMP_A2(SCMP_CMP_MASKED_EQ, flag, flag));
        rule(SCMP_ACT_KILL_PROCESS, SCMP_SYS(open), 1, SCMP_A1(SCMP_CMP_MASKED_EQ, flag, flag));
    }
    // Writing: standard output and error (both /dev/null) and the pipe, descriptor 3.
    for (const uint64_t fd : {1u, 2u, 3u}) {
        rule(SCMP_ACT_ALLOW, SCMP_SYS(write), 1, SCMP_A0(SCMP_CMP_EQ, fd));
        rule(SCMP_ACT_ALLOW, SCMP_SYS(writev), 1, SCMP_A0(SCMP_CMP_EQ, fd));
    }
    // Memory: no executable mappings.
    for (const int s : {SCMP_SYS(mmap), SCMP_SYS(mprotect)}) {
        rule(SCMP_ACT_ALLOW, s, 1, SCMP_A2(SCMP_CMP_MASKED_EQ, uint64_t{PROT_EXEC}, 0));
    }
    // abort() and raise() signal the process itself.
    rule(SCMP_ACT_ALLOW, SCMP_SYS(tgkill), 1,
         SCMP_A0(SCMP_CMP_EQ, static_cast<uint64_t>(::getpid())));
    // stdio asks whether an output is a terminal; the answer is no.
    rc = rc ? rc : seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOTTY), SCMP_SYS(ioctl), 0);
    for (const int s : {SCMP_SYS(read),          SCMP_SYS(pread64),      SCMP_SYS(readv),
                        SCMP_SYS(lseek),         SCMP_SYS(close),        SCMP_SYS(fstat),
                        SCMP_SYS(newfstatat),    SCMP_SYS(statx),        SCMP_SYS(stat),
                        SCMP_SYS(lstat),         SCMP_SYS(access),       SCMP_SYS(faccessat),
                        SCMP_SYS(faccessat2),    SCMP_SYS(getcwd),       SCMP_SYS(readlink),
                        SCMP_SYS(getdents64),    SCMP_SYS(fcntl),        SCMP_SYS(brk),
                        SCMP_SYS(munmap),        SCMP_SYS(mremap),       SCMP_SYS(madvise),
                        SCMP_SYS(futex),         SCMP_SYS(getpid),       SCMP_SYS(gettid),
                        SCMP_SYS(clock_gettime), SCMP_SYS(getrandom),    SCMP_SYS(rt_sigprocmask),
                        SCMP_SYS(rt_sigaction),  SCMP_SYS(rt_sigreturn), SCMP_SYS(sched_yield),
                        SCMP_SYS(exit),          SCMP_SYS(exit_group)}) {
        allow(s);
    }
    return rc;
}

} // namespace

bool applyLimits(uint64_t memoryBytes, std::string& error) {
    bool ok = setLimit(RLIMIT_CORE, 0) && setLimit(RLIMIT_FSIZE, 0) && setLimit(RLIMIT_NOFILE, 64);
    // A backstop should the parent die without killing us: an hour of CPU.
    ok = ok && setLimit(RLIMIT_CPU, 3600);
    if (!kSanitizerBuild) {
        ok = ok && setLimit(RLIMIT_AS, static_cast<rlim_t>(memoryBytes));
    }
    if (!ok) {
        error = std::string("cannot set the importer's limits: ") + std::strerror(errno);
    }
    return ok;
}

bool enterSandbox(std::string& error) {
    const bool strict = !kSanitizerBuild;
    Filter filter(strict ? SCMP_ACT_KILL_PROCESS : SCMP_ACT_ALLOW);
    if (filter.ctx == nullptr) {
        error = "cannot make the importer's syscall filter";
        return false;
    }
    int rc = addRules(filter.ctx, strict);
    rc = rc ? rc : seccomp_load(filter.ctx);
    if (rc != 0) {
        error = std::string("cannot load the importer's syscall filter: ") + std::strerror(-rc);
        return false;
    }
    return true;
}

} // namespace raylab::import
