// ubii-node end to end against the real master (the `master` fixture, the npm master): each
// command's output and exit code, the errors included; plugin loading and `run` without sessions
// (the npm master assigns none; cli_session_test.cpp runs them on the current master).

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#ifdef UBII_CLI_TEST_WITH_OPENCV
#include <opencv2/imgcodecs.hpp>
#endif

#include "cli_process.hpp"

namespace
{

using namespace std::chrono_literals;
using ubii_cli_test::Outcome;
using ubii_cli_test::Process;

const std::string cli = UBII_NODE_CLI;
const std::string plugins = UBII_TEST_PLUGIN_DIR;

int port_base()
{
    const char *base = std::getenv("UBII_TEST_PORT_BASE");
    return base != nullptr ? std::atoi(base) : 8101;
}

std::string service_url()
{
    return "tcp://127.0.0.1:" + std::to_string(port_base());
}

// `ubii-node --service-url URL ARGS...`.
std::vector<std::string> with_master(std::vector<std::string> arguments)
{
    arguments.insert(arguments.begin(), {"--service-url", service_url()});
    return arguments;
}

Outcome cli_run(std::vector<std::string> arguments, std::chrono::milliseconds timeout = 30s)
{
    return ubii_cli_test::run(cli, with_master(std::move(arguments)), timeout);
}

std::vector<std::string> lines(const std::string &text)
{
    std::vector<std::string> result;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        result.push_back(text.substr(start, end - start));
        start = end == std::string::npos ? text.size() : end + 1;
    }
    return result;
}

bool has(const std::string &text, const std::string &part)
{
    return text.find(part) != std::string::npos;
}

// A `sub` in the background, returned once the master has its subscription.
std::unique_ptr<Process> subscriber(std::vector<std::string> arguments)
{
    arguments.insert(arguments.begin(), {"-v", "sub"});
    auto process = std::make_unique<Process>(cli, with_master(std::move(arguments)));
    const bool subscribed = process->read_until(
        [](const std::string &, const std::string &err) { return has(err, "subscribed to"); }, 20s);
    EXPECT_TRUE(subscribed) << process->err();
    return process;
}

std::string temporary_file(const std::string &name, const std::string &content)
{
    const std::string path = std::string(UBII_CLI_TEST_WORK_DIR) + "/" + name;
    std::ofstream(path) << content;
    return path;
}

} // namespace

TEST(CliInfo, PrintsTheServerConfigurationAsTextAndJson)
{
    const Outcome text = cli_run({"info"});
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_TRUE(has(text.out, "portServiceZmq: " + std::to_string(port_base()))) << text.out;
    EXPECT_TRUE(has(text.out, "constantsJson: <")) << "kilobytes of constants are summarised";

    const Outcome json = cli_run({"info", "--json"});
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const auto server = nlohmann::json::parse(json.out);
    EXPECT_EQ(server["portTopicDataZmq"], std::to_string(port_base() + 2));
    EXPECT_FALSE(server["id"].get<std::string>().empty());
}

TEST(CliList, ServicesAsATableAndAsJson)
{
    const Outcome table = cli_run({"list", "services"});
    ASSERT_EQ(table.exit_code, 0) << table.err;
    const auto rows = lines(table.out);
    ASSERT_GT(rows.size(), 5u);
    EXPECT_EQ(rows[0].rfind("TOPIC ", 0), 0u) << rows[0];
    EXPECT_TRUE(has(table.out, "/services/topic_list")) << table.out;

    const Outcome json = cli_run({"list", "services", "--json"});
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const auto services = nlohmann::json::parse(json.out);
    ASSERT_TRUE(services.is_array());
    EXPECT_EQ(services.size(), rows.size() - 1);
    bool found = false;
    for (const auto &service : services)
        found = found || service["topic"] == "/services/server_configuration";
    EXPECT_TRUE(found) << json.out;
}

TEST(CliList, TopicsOnePerLineAndAnUnknownKindIsAUsageError)
{
    const Outcome topics = cli_run({"list", "topics"});
    ASSERT_EQ(topics.exit_code, 0) << topics.err;
    EXPECT_TRUE(has(topics.out, "/services/topic_list\n")) << topics.out;

    const Outcome wrong = cli_run({"list", "planets"});
    EXPECT_EQ(wrong.exit_code, 2);
    EXPECT_TRUE(has(wrong.err, "planets")) << wrong.err;
}

TEST(CliList, AServiceTheNpmMasterLacksIsTheMastersError)
{
    // The npm 0.4.0 master has no /services/client/get_list.
    const Outcome clients = cli_run({"list", "clients"});
    EXPECT_EQ(clients.exit_code, 1);
    EXPECT_TRUE(has(clients.err, "/services/client/get_list: the master answered with an error"))
        << clients.err;
}

TEST(CliCall, AnyServiceWithAJsonRequestPrintsTheReplyAsJson)
{
    const Outcome reply = cli_run({"call", "/services/topic_list"});
    ASSERT_EQ(reply.exit_code, 0) << reply.err;
    const auto json = nlohmann::json::parse(reply.out);
    ASSERT_TRUE(json.contains("stringList")) << reply.out;
    EXPECT_FALSE(json["stringList"]["elements"].empty());

    const Outcome server = cli_run({"call", "/services/server_configuration", "--json", "{}"});
    ASSERT_EQ(server.exit_code, 0) << server.err;
    EXPECT_EQ(nlohmann::json::parse(server.out)["server"]["portServiceZmq"],
              std::to_string(port_base()));
}

TEST(CliCall, UnknownServiceBadJsonAndNoMasterEachHaveTheirExitCode)
{
    const Outcome unknown = cli_run({"call", "/services/no_such_service"});
    EXPECT_EQ(unknown.exit_code, 1);
    EXPECT_TRUE(has(unknown.err, "/services/no_such_service: the master answered with an error"))
        << unknown.err;

    const Outcome bad_json =
        cli_run({"call", "/services/topic_list", "--json", "{\"stringList\":"});
    EXPECT_EQ(bad_json.exit_code, 2);
    EXPECT_TRUE(has(bad_json.err, "not a ServiceRequest in JSON")) << bad_json.err;

    const Outcome no_master = ubii_cli_test::run(
        cli, {"--service-url", "tcp://127.0.0.1:" + std::to_string(port_base() + 90),
              "--connect-timeout", "1", "info"});
    EXPECT_EQ(no_master.exit_code, 3);
    EXPECT_TRUE(has(no_master.err, "was not reachable within 1000 ms")) << no_master.err;
}

TEST(CliPubSub, RecordsOfSeveralTypesArriveAsTextAndAsJson)
{
    auto text = subscriber({"/cli/test/mixed", "--count", "5", "--timeout", "20"});
    auto json = subscriber({"/cli/test/mixed", "--count", "5", "--timeout", "20", "--json"});
    for (const std::vector<std::string> &pub :
         {std::vector<std::string>{"pub", "/cli/test/mixed", "42.5"},
          {"pub", "/cli/test/mixed", "1,2,3", "--type", "vector3"},
          {"pub", "/cli/test/mixed", "hello world", "--type", "string"},
          {"pub", "/cli/test/mixed", "[1.5, -2]", "--type", "double_list"},
          {"pub", "/cli/test/mixed", "{\"color\": {\"r\": 1, \"a\": 0.5}}", "--type", "json"}}) {
        const Outcome published = cli_run(pub);
        ASSERT_EQ(published.exit_code, 0) << published.err;
    }
    const Outcome text_outcome = text->finish(20s);
    EXPECT_EQ(text_outcome.exit_code, 0) << text_outcome.err;
    EXPECT_EQ(lines(text_outcome.out),
              (std::vector<std::string>{"/cli/test/mixed double 42.5",
                                        "/cli/test/mixed vector3 {x: 1, y: 2, z: 3}",
                                        "/cli/test/mixed string hello world",
                                        "/cli/test/mixed double_list {elements: [1.5, -2]}",
                                        "/cli/test/mixed color {r: 1, a: 0.5}"}));

    const Outcome json_outcome = json->finish(20s);
    ASSERT_EQ(json_outcome.exit_code, 0) << json_outcome.err;
    const auto records = lines(json_outcome.out);
    ASSERT_EQ(records.size(), 5u) << json_outcome.out;
    const auto vector3 = nlohmann::json::parse(records[1]);
    EXPECT_EQ(vector3["topic"], "/cli/test/mixed");
    EXPECT_EQ(vector3["type"], "vector3");
    EXPECT_EQ(vector3["value"], (nlohmann::json{{"x", 1.0}, {"y", 2.0}, {"z", 3.0}}));
    EXPECT_EQ(nlohmann::json::parse(records[4])["value"], (nlohmann::json{{"r", 1.0}, {"a", 0.5}}));
}

TEST(CliPubSub, ARatedSeriesArrivesWholeAndInOrderAndARegexSubscriptionSeesIt)
{
    auto sub =
        subscriber({"^/cli/test/series/[a-z]+$", "--regex", "--count", "5", "--timeout", "20"});
    const Outcome published = cli_run(
        {"pub", "/cli/test/series/abc", "7", "--type", "int32", "--rate", "20", "--count", "5"});
    ASSERT_EQ(published.exit_code, 0) << published.err;
    const Outcome outcome = sub->finish(20s);
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_EQ(lines(outcome.out), std::vector<std::string>(5, "/cli/test/series/abc int32 7"));
}

TEST(CliPubSub, WrongValuesAreUsageErrorsBeforeAnyMasterIsAsked)
{
    const std::vector<std::vector<std::string>> wrong{
        {"pub", "/x", "abc", "--type", "double"},
        {"pub", "/x", "1,2", "--type", "bool"},
        {"pub", "/x", "1,2,3,4,5", "--type", "vector3"},
        {"pub", "/x", "3000000000", "--type", "int32"},
        {"pub", "/x", "{\"nope\": 1}", "--type", "json"},
        {"pub", "/x", "1", "--type", "planet"},
        {"pub", "/x"},
    };
    for (const auto &arguments : wrong) {
        // No master at this port: a usage error must come first.
        std::vector<std::string> command{"--service-url", "tcp://127.0.0.1:1", "--connect-timeout",
                                         "1"};
        command.insert(command.end(), arguments.begin(), arguments.end());
        const Outcome outcome = ubii_cli_test::run(cli, command);
        EXPECT_EQ(outcome.exit_code, 2) << arguments[2] << ": " << outcome.err;
        EXPECT_FALSE(outcome.err.empty());
    }
}

TEST(CliPubSub, TooFewRecordsWithinTheTimeoutExitWithFour)
{
    const Outcome outcome = cli_run({"sub", "/cli/test/silence", "--count", "1", "--timeout", "1"});
    EXPECT_EQ(outcome.exit_code, 4);
    EXPECT_TRUE(has(outcome.err, "received 0 of 1 records on /cli/test/silence within 1 s"))
        << outcome.err;
}

#ifdef UBII_CLI_TEST_WITH_OPENCV
TEST(CliPubSub, AnImageFileIsPublishedAsAnImage2DAndSummarised)
{
    const std::string path = std::string(UBII_CLI_TEST_WORK_DIR) + "/gradient.png";
    cv::Mat image(30, 40, CV_8UC3, cv::Scalar(10, 20, 30));
    ASSERT_TRUE(cv::imwrite(path, image));
    auto sub = subscriber({"/cli/test/image", "--count", "1", "--timeout", "20"});
    const Outcome published = cli_run({"pub", "/cli/test/image", "--image", path});
    ASSERT_EQ(published.exit_code, 0) << published.err;
    const Outcome outcome = sub->finish(20s);
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_EQ(outcome.out, "/cli/test/image image2D {width: 40, height: 30, data_format: RGB8, "
                           "data: <3600 bytes>}\n");

    const Outcome not_image =
        cli_run({"pub", "/cli/test/image", "--image", plugins + "/bad/text_file.so"});
    EXPECT_EQ(not_image.exit_code, 2);
    EXPECT_TRUE(has(not_image.err, "is not an image file")) << not_image.err;
}
#endif

TEST(CliSession, BadSpecFilesAreUsageErrorsAndListWorks)
{
    const Outcome missing = cli_run({"session", "start", "/nonexistent/spec.json"});
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_TRUE(has(missing.err, "cannot read the session spec")) << missing.err;

    const std::string bad = temporary_file("bad_session.json", "{\"nmae\": \"typo\"}");
    const Outcome typo = cli_run({"session", "start", bad});
    EXPECT_EQ(typo.exit_code, 2);
    EXPECT_TRUE(has(typo.err, "is not a ubii.sessions.Session in JSON")) << typo.err;

    const Outcome list = cli_run({"session", "list"});
    EXPECT_EQ(list.exit_code, 0) << list.err;
}

TEST(CliModules, TheGoodPluginsModulesAreListedWithoutAMaster)
{
    const Outcome table = ubii_cli_test::run(
        cli, {"modules", "--no-default-modules", "--modules", plugins + "/good"});
    ASSERT_EQ(table.exit_code, 0) << table.err;
    const auto rows = lines(table.out);
    ASSERT_EQ(rows.size(), 3u) << table.out;
    EXPECT_EQ(rows[1].rfind("plugin_negate ", 0), 0u);
    EXPECT_EQ(rows[2].rfind("plugin_scale ", 0), 0u);

    // UBII_MODULE_PATH is looked in, before the installation's plugins (in the build tree: the
    // OCR plugin, where it is built).
    const Outcome json = ubii_cli_test::run(cli, {"modules", "--json"}, 30s,
                                            {"UBII_MODULE_PATH=" + plugins + "/good"});
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const auto specs = nlohmann::json::parse(json.out);
    const auto scale = std::find_if(specs.begin(), specs.end(), [](const auto &spec) {
        return spec["name"] == "plugin_scale";
    });
    ASSERT_NE(scale, specs.end()) << json.out;
    EXPECT_EQ((*scale)["file"], plugins + "/good/good_plugin.so");
}

TEST(CliModules, EveryRefusalIsOneLineNamingItsFileAndTheRestLoads)
{
    const Outcome outcome =
        ubii_cli_test::run(cli, {"modules", "--no-default-modules", "--modules", plugins + "/good",
                                 "--modules", plugins + "/bad"});
    EXPECT_EQ(outcome.exit_code, 5);
    const std::string bad = plugins + "/bad/";
    for (const std::string &expected :
         {bad + "missing_symbol_plugin.so: cannot be loaded: ",
          bad + "mixed_plugin.so: module 2 of 3 refused: a processing module named "
                "\"plugin_scale\" is registered already",
          bad + "mixed_plugin.so: module 3 of 3 refused: no licence for this module",
          bad + "no_entry_plugin.so: not a libubii plugin",
          bad + "other_abi_plugin.so: refused: "
                "built for plugin ABI 99",
          bad + "other_version_plugin.so: refused: built against libubii",
          bad + "text_file.so: cannot be loaded",
          bad + "throwing_list_plugin.so: refused: its "
                "factory list threw"})
        EXPECT_TRUE(has(outcome.err, "ubii-node: " + expected)) << expected << "\n" << outcome.err;
    EXPECT_EQ(lines(outcome.err).size(), 8u) << outcome.err;
    EXPECT_EQ(lines(outcome.out).size(), 4u) << outcome.out; // header + three modules

    const Outcome absent = ubii_cli_test::run(cli, {"modules", "--modules", "/nonexistent"});
    EXPECT_EQ(absent.exit_code, 2);
}

TEST(CliRun, ModuleArgumentsAndNamesAreCheckedBeforeConnecting)
{
    const std::vector<std::pair<std::vector<std::string>, int>> cases{
        {{"--module-arg", "plugin_scale:factor=0"}, 2},
        {{"--module-arg", "plugin_scale:fator=3"}, 2},
        {{"--module-arg", "plugin_scale=3"}, 2},
        {{"--module-arg", "plugin_unknown:factor=3"}, 2},
        {{"plugin_unknown"}, 5},
    };
    for (const auto &[extra, code] : cases) {
        std::vector<std::string> command{"--service-url", "tcp://127.0.0.1:1",
                                         "run",           "--no-default-modules",
                                         "--modules",     plugins + "/good"};
        command.insert(command.end(), extra.begin(), extra.end());
        const Outcome outcome = ubii_cli_test::run(cli, command);
        EXPECT_EQ(outcome.exit_code, code) << extra.back() << ": " << outcome.err;
    }
    const Outcome refused = ubii_cli_test::run(
        cli, {"run", "--modules", plugins + "/good", "--module-arg", "plugin_scale:factor=0"});
    EXPECT_TRUE(has(refused.err, "factor 0 would scale everything away")) << refused.err;
    const Outcome nothing = ubii_cli_test::run(cli, {"run", "--no-default-modules"});
    EXPECT_EQ(nothing.exit_code, 5);
    EXPECT_TRUE(has(nothing.err, "no processing modules to offer")) << nothing.err;
}

TEST(CliRun, ServesUntilInterruptedReportsTimingOnSigusr1AndDeregisters)
{
    Process run(cli,
                with_master({"run", "--no-default-modules", "--modules", plugins + "/good",
                             "--module-arg", "plugin_scale:factor=3", "--name", "cli-run-test"}));
    ASSERT_TRUE(run.read_until(
        [](const std::string &out, const std::string &) {
            return has(out, "offering plugin_negate, plugin_scale");
        },
        20s))
        << run.out() << run.err();
    EXPECT_TRUE(has(run.out(), "connected as client ")) << run.out();
    run.signal(SIGUSR1);
    ASSERT_TRUE(run.read_until(
        [](const std::string &out, const std::string &) { return has(out, "timing: "); }, 10s))
        << run.out();
    run.signal(SIGINT);
    const Outcome outcome = run.finish(20s);
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_TRUE(has(outcome.out, "stopping\n")) << outcome.out;
    EXPECT_TRUE(has(outcome.out, " stopped\n")) << "deregistration not confirmed:\n" << outcome.out;
}
