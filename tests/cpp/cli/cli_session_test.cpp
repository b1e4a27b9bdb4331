// ubii-node against the current master, which assigns session modules to nodes: `run` with a
// plugin from a directory serves a session that `session start` began, `sub` sees its output, and
// `session stop` ends it. Registered only with -DUBII_CURRENT_MASTER_SOURCE (never in CI).

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <string>
#include <vector>

#include "cli_process.hpp"

namespace
{

using namespace std::chrono_literals;
using ubii_cli_test::Outcome;
using ubii_cli_test::Process;

const std::string cli = UBII_NODE_CLI;
const std::string plugins = UBII_TEST_PLUGIN_DIR;
const std::string service_url = "tcp://127.0.0.1:8401";

std::vector<std::string> with_master(std::vector<std::string> arguments)
{
    arguments.insert(arguments.begin(), {"--service-url", service_url});
    return arguments;
}

bool has(const std::string &text, const std::string &part)
{
    return text.find(part) != std::string::npos;
}

auto printed(const std::string &part)
{
    return [part](const std::string &out, const std::string &) { return has(out, part); };
}

const char session_spec[] = R"({
  "name": "cli-session-test",
  "processingModules": [{"name": "plugin_scale"}],
  "ioMappings": [{
    "processingModuleName": "plugin_scale",
    "inputMappings": [{"inputName": "value", "topic": "/cli/session/in"}],
    "outputMappings": [{"outputName": "scaled", "topic": "/cli/session/out"}]
  }]
})";

} // namespace

TEST(CliSessionOnTheCurrentMaster, RunServesAPluginModuleASessionStartedFromTheCommandLine)
{
    Process run(cli, with_master({"run", "--no-default-modules", "--modules", plugins + "/good",
                                  "--module-arg", "plugin_scale:factor=10", "--name",
                                  "cli-session-runner"}));
    ASSERT_TRUE(run.read_until(printed("offering plugin_negate, plugin_scale"), 20s))
        << run.out() << run.err();

    Process sub(cli,
                with_master({"-v", "sub", "/cli/session/out", "--count", "2", "--timeout", "40"}));
    ASSERT_TRUE(sub.read_until(
        [](const std::string &, const std::string &err) { return has(err, "subscribed"); }, 20s))
        << sub.err();

    const std::string spec_path = std::string(UBII_CLI_TEST_WORK_DIR) + "/session.json";
    std::ofstream(spec_path) << session_spec;
    const Outcome started = ubii_cli_test::run(cli, with_master({"session", "start", spec_path}));
    ASSERT_EQ(started.exit_code, 0) << started.err;
    const std::string session_id = started.out.substr(0, started.out.find(' '));
    ASSERT_FALSE(session_id.empty()) << started.out;
    ASSERT_TRUE(run.read_until(printed("confirmed_started plugin_scale"), 20s)) << run.out();
    EXPECT_TRUE(has(run.out(), "session=" + session_id)) << run.out();

    // One publishing process: the current master forgets a topic (and its subscriptions) when
    // the client that published it leaves.
    const Outcome published = ubii_cli_test::run(
        cli, with_master({"pub", "/cli/session/in", "4.2", "--rate", "5", "--count", "2"}));
    ASSERT_EQ(published.exit_code, 0) << published.err;
    const Outcome seen = sub.finish(40s);
    EXPECT_EQ(seen.exit_code, 0) << seen.err;
    EXPECT_EQ(seen.out, "/cli/session/out double 42\n/cli/session/out double 42\n");

    const Outcome stopped = ubii_cli_test::run(cli, with_master({"session", "stop", session_id}));
    EXPECT_EQ(stopped.exit_code, 0) << stopped.err;
    EXPECT_TRUE(has(stopped.out, session_id + " STOPPED")) << stopped.out;
    EXPECT_TRUE(run.read_until(printed("confirmed_removed plugin_scale"), 20s)) << run.out();

    run.signal(SIGINT);
    const Outcome ended = run.finish(20s);
    EXPECT_EQ(ended.exit_code, 0) << ended.err;
    EXPECT_TRUE(has(ended.out, "stopped plugin_scale")) << ended.out;
    EXPECT_TRUE(has(ended.out, " stopped\n")) << ended.out;
}
