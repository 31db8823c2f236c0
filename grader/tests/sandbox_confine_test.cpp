// The container mode (RT_GRADE_ISOLATION=uid: root without namespaces, as on Gradescope): a
// child confined by Landlock and seccomp (grader/confine.h) reaches no network, reads no host
// file outside /usr and its inputs, and writes only its output folder and its scratch folder.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "sandbox/confine.h"
#include "sandbox/sandbox.h"
#include "testing/skip.h"

namespace {

namespace fs = std::filesystem;
using rt::grader::RunResult;
using rt::grader::RunSpec;

// Before any run probes the isolation (once per process): every test here is in container mode.
const bool kForced = setenv("RT_GRADE_ISOLATION", "uid", 1) == 0;

class SandboxConfine : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(kForced);
        dir_ = fs::temp_directory_path() / ("rt-sandbox-confine-" + std::to_string(getpid()));
        fs::create_directories(dir_ / "out");
        // Other uids must reach the output folder (the grader's run folders are 0711 too).
        fs::permissions(dir_,
                        fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
    }
    void TearDown() override { fs::remove_all(dir_); }

    RunResult run(const std::string& script) {
        RunSpec spec;
        spec.argv = {"/bin/bash", "-c", script};
        spec.working_dir = dir_ / "out";
        spec.capture_dir = dir_ / "capture";
        spec.binds = {{dir_ / "out", {}, true}};
        spec.limits.cpu_seconds = 10;
        spec.limits.wall_seconds = 60;
        return rt::grader::run_sandboxed(spec);
    }

    fs::path dir_;
};

TEST_F(SandboxConfine, TheChildCannotOpenATcpConnection) {
    if (!rt::grader::probe_confinement().seccomp &&
        rt::grader::probe_confinement().landlock_abi < 4)
        RT_SKIP_IN_STARTER_TREE() << "neither seccomp nor Landlock ABI 4 here: the report says so";
    // A listener of this (trusted) process on 127.0.0.1.
    const int listener = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    ASSERT_GE(listener, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof address;
    ASSERT_EQ(bind(listener, reinterpret_cast<sockaddr*>(&address), size), 0);
    ASSERT_EQ(listen(listener, 4), 0);
    ASSERT_EQ(getsockname(listener, reinterpret_cast<sockaddr*>(&address), &size), 0);
    const std::string port = std::to_string(ntohs(address.sin_port));
    const auto result = run("exec 3<>/dev/tcp/127.0.0.1/" + port + " && echo CONNECTED; echo done");
    EXPECT_NE(result.output.find("done"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("CONNECTED"), std::string::npos) << result.output;
    EXPECT_LT(accept(listener, nullptr, nullptr), 0) << "the listener saw a connection";
    close(listener);
}

TEST_F(SandboxConfine, TheChildCannotReadTheHostsEtc) {
    if (rt::grader::probe_confinement().landlock_abi == 0)
        RT_SKIP_IN_STARTER_TREE() << "no Landlock here";
    std::ifstream passwd("/etc/passwd");
    std::string first;
    ASSERT_TRUE(std::getline(passwd, first)) << "no /etc/passwd to protect";
    const auto result = run("cat /etc/passwd; echo done");
    EXPECT_NE(result.output.find("done"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find(first), std::string::npos) << result.output;
}

TEST_F(SandboxConfine, TheChildCannotWriteTheHostsTmp) {
    if (rt::grader::probe_confinement().landlock_abi == 0)
        RT_SKIP_IN_STARTER_TREE() << "no Landlock here";
    const std::string name = "rt-sandbox-confine-canary-" + std::to_string(getpid());
    const auto result =
        run("for d in /tmp /var/tmp /dev/shm; do echo x > $d/" + name + "; done; echo done");
    EXPECT_NE(result.output.find("done"), std::string::npos) << result.output;
    for (const char* d : {"/tmp/", "/var/tmp/", "/dev/shm/"}) {
        EXPECT_FALSE(fs::exists(d + name)) << d << name << " written";
        fs::remove(d + name);
    }
}

TEST_F(SandboxConfine, TheChildWritesItsOutputAndAScratchFolderThatIsRemoved) {
    const auto result = run(
        "echo ok > written && echo tmp > \"$TMPDIR/t\" && cat \"$TMPDIR/t\" && echo \"$TMPDIR\"");
    ASSERT_TRUE(result.ok()) << result.describe({}) << "\n" << result.output;
    std::ifstream written(dir_ / "out" / "written");
    std::string text;
    EXPECT_TRUE(std::getline(written, text) && text == "ok");
    // Its TMPDIR: a folder of its own, not the host's /tmp, gone after the run.
    const std::string scratch = result.output.substr(result.output.rfind("tmp\n") + 4);
    const fs::path tmpdir = scratch.substr(0, scratch.find('\n'));
    EXPECT_NE(tmpdir, fs::path("/tmp"));
    EXPECT_FALSE(tmpdir.empty());
    EXPECT_FALSE(fs::exists(tmpdir)) << tmpdir << " left behind";
}

TEST_F(SandboxConfine, TheReportNamesWhatConfinesTheChild) {
    const auto confinement = rt::grader::probe_confinement();
    const std::string text = rt::grader::describe(rt::grader::probe_isolation());
    EXPECT_NE(text.find(confinement.landlock_abi > 0 ? "Landlock (ABI" : "no Landlock"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(confinement.seccomp ? "seccomp refuses" : "no seccomp"), std::string::npos)
        << text;
}

}  // namespace
