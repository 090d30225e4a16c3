#include "GnuplotRunner.h"

#include <cerrno>
#include <cstring>
#include <spawn.h>
#include <sys/wait.h>

extern char** environ;  // POSIX: the process environment, handed to gnuplot

namespace shadowmap_bench {

std::string runGnuplot(const std::filesystem::path& script, const std::string& outputName) {
    // posix_spawnp with an argument vector: no shell, so no quoting of paths.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string folder = script.parent_path().empty() ? "." : script.parent_path().string();
    posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
    std::string program = "gnuplot", flag = "-e", assignment = "output='" + outputName + "'";
    std::string file = script.filename().string();
    char* argv[] = {program.data(), flag.data(), assignment.data(), file.data(), nullptr};
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned == ENOENT) return "gnuplot not found (Debian package gnuplot-nox)";
    if (spawned != 0) return std::string("cannot run gnuplot: ") + std::strerror(spawned);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return std::string("waiting for gnuplot: ") + std::strerror(errno);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return "gnuplot failed on " + script.string() + " (status " + std::to_string(status) + ")";
    return "";
}

} // namespace shadowmap_bench
