#include "test_hooks.h"

#include "pipe_output.h"

#include <arpa/inet.h>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <netinet/in.h>
#include <string_view>
#include <sys/socket.h>
#include <unistd.h>

namespace raylab::import {

void runTestHook() {
    const char* hook = std::getenv("RAYLAB_IMPORT_TEST_CRASH");
    if (hook == nullptr) {
        return;
    }
    const std::string_view what(hook);
    if (what == "segv") {
        // The default disposition, as a release build has it: a sanitizer's runtime would
        // otherwise catch the signal, report it and exit with a code of its own.
        std::signal(SIGSEGV, SIG_DFL);
        std::raise(SIGSEGV);
    } else if (what == "abort") {
        std::abort();
    } else if (what == "hang") {
        volatile unsigned long spin = 0;
        for (;;) {
            spin = static_cast<unsigned long>(spin) + 1; // a volatile store the loop cannot skip
        }
    } else if (what == "write") {
        const int fd = ::open("/tmp/raylab-import-escape", O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (fd >= 0) {
            ::close(fd);
        }
    } else if (what == "socket") {
        const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = htons(9);
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        (void)::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
    } else if (what == "exec") {
        char* const argv[] = {const_cast<char*>("/bin/true"), nullptr};
        ::execv(argv[0], argv);
    } else if (what == "exit") {
        std::_Exit(66);
    } else if (what == "print") {
        std::printf("nullptr returned by creating DDLNode.\n");
        std::cerr << "a second line\x1b[31m, on stderr\n";
    } else if (what == "garbage") {
        sendToParent({'n', 'o', 't', ' ', 'a', ' ', 's', 't', 'r', 'e', 'a', 'm'});
        std::_Exit(0);
    }
}

} // namespace raylab::import
