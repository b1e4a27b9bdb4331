// OCR benchmark: per-frame time of every pipeline on every synthetic scene (count, mean, relative
// standard deviation, median: the thesis's table format), with word precision/recall, beside the
// tesseract command-line tool and a bare TessBaseAPI call on the same image and settings, and the
// thesis's published figures. Prints a Markdown table; asserts nothing.
//
//   ocr_bench [--frames N] [--cli-runs N] [--east-model PATH] [--east-input WxH] [--save DIR]

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <tesseract/baseapi.h>
#include <tesseract/resultiterator.h>
#include <unistd.h>

#include "frame_timing.hpp"
#include "scenes.hpp"
#include "ubii/ocr/ocr.hpp"

namespace
{

using ubii::bench::FrameStats;
using ubii::bench::time_frames;
namespace ocr = ubii::ocr;

constexpr int warm_up_frames = 2;
constexpr int source_resolution_dpi = 300;

struct Arguments {
    int frames = 50;
    int cli_runs = 10;
    std::string east_model;
    std::optional<cv::Size> east_input;
    std::string save_dir;
};

Arguments parse(int argc, char **argv)
{
    Arguments args;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i], value = argv[i + 1];
        if (flag == "--frames")
            args.frames = std::stoi(value);
        else if (flag == "--cli-runs")
            args.cli_runs = std::stoi(value);
        else if (flag == "--east-model")
            args.east_model = value;
        else if (flag == "--east-input") {
            int width = 0, height = 0;
            if (std::sscanf(value.c_str(), "%dx%d", &width, &height) != 2)
                throw ocr::InvalidArgument("--east-input wants WxH, e.g. 320x320");
            args.east_input = cv::Size(width, height);
        } else if (flag == "--save")
            args.save_dir = value;
        else
            throw ocr::InvalidArgument("unknown option " + flag);
    }
    return args;
}

// Automatic segmentation for the page-like baseline; sparse text for the scenes (the thesis's
// setting for the webcam frame; on the sign automatic segmentation finds no text at all here).
ocr::Segmentation segmentation_for(const std::string &scene)
{
    return scene == "baseline" ? ocr::Segmentation::automatic : ocr::Segmentation::sparse_text;
}

// Published per-frame means (ms, i5-8265U), by pipeline and scene.
const std::map<std::string, std::map<std::string, double>> thesis_ms = {
    {"pure", {{"baseline", 50}, {"sign", 137}, {"webcam", 67}}},
    {"east", {{"baseline", 135}, {"sign", 199}, {"webcam", 134}}},
    {"mser", {{"baseline", 74}, {"sign", 245}, {"webcam", 148}}},
};

ocr::PipelineOptions options_for(ocr::PipelineKind kind, const ocr::testdata::Scene &scene,
                                 const Arguments &args)
{
    auto options = ocr::default_options(kind);
    if (kind == ocr::PipelineKind::pure)
        ocr::tesseract_options(options).segmentation = segmentation_for(scene.name);
    if (auto *east = std::get_if<ocr::EastOptions>(&options)) {
        east->model_path = args.east_model;
        east->input_size = args.east_input.value_or(cv::Size(320, 320));
    }
    return options;
}

// What a program would write without libubii: one TessBaseAPI, the gray frame, words read back.
class BareTesseract
{
  public:
    explicit BareTesseract(ocr::Segmentation segmentation)
    {
        if (api_.Init(nullptr, "eng", tesseract::OEM_LSTM_ONLY) != 0)
            throw ocr::EngineError("bare TessBaseAPI: no eng traineddata");
        api_.SetPageSegMode(static_cast<tesseract::PageSegMode>(segmentation));
    }
    ~BareTesseract()
    {
        api_.End();
    }

    std::size_t read(const cv::Mat &gray)
    {
        api_.SetImage(gray.data, gray.cols, gray.rows, 1, static_cast<int>(gray.step[0]));
        api_.SetSourceResolution(source_resolution_dpi);
        api_.Recognize(nullptr);
        std::size_t words = 0;
        const std::unique_ptr<tesseract::ResultIterator> word(api_.GetIterator());
        if (word) {
            do {
                const std::unique_ptr<char[]> text(word->GetUTF8Text(tesseract::RIL_WORD));
                int left = 0, top = 0, right = 0, bottom = 0;
                if (text && word->Confidence(tesseract::RIL_WORD) >= 0.0f &&
                    word->BoundingBox(tesseract::RIL_WORD, &left, &top, &right, &bottom))
                    ++words;
            } while (word->Next(tesseract::RIL_WORD));
        }
        return words;
    }

  private:
    tesseract::TessBaseAPI api_;
};

// `threads`: limited (OMP_THREAD_LIMIT=1, as the pipelines run) or as installed (Debian's build
// starts an OpenMP thread per core, which is how a user running the CLI gets it).
enum class CliThreads { limited, as_installed };

std::optional<FrameStats> time_cli(const std::string &image_path, ocr::Segmentation segmentation,
                                   int runs, CliThreads threads)
{
    const std::string cli = UBII_TESSERACT_CLI;
    if (cli.empty())
        return std::nullopt;
    const std::string environment =
        threads == CliThreads::as_installed ? "env -u OMP_THREAD_LIMIT " : "";
    const std::string command = environment + "'" + cli + "' '" + image_path +
                                "' stdout -l eng --oem 1 --psm " +
                                std::to_string(static_cast<int>(segmentation)) + " --dpi " +
                                std::to_string(source_resolution_dpi) + " >/dev/null 2>&1";
    bool failed = false;
    const auto stats = time_frames(1, runs, [&] { failed |= std::system(command.c_str()) != 0; });
    if (failed)
        return std::nullopt;
    return stats;
}

std::pair<FrameStats, FrameStats> ocr_bench_interleaved(int frames,
                                                        const std::function<void()> &pipeline,
                                                        const std::function<void()> &bare)
{
    return ubii::bench::time_frames_interleaved(warm_up_frames, frames, pipeline, bare);
}

std::string fixed(double value, int decimals)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

} // namespace

int main(int argc, char **argv)
{
    ocr::ensure_single_omp_thread(argc, argv);
    try {
        const Arguments args = parse(argc, argv);
        char temp_template[] = "/tmp/ocr_bench.XXXXXX";
        const std::string temp_dir = args.save_dir.empty() ? mkdtemp(temp_template) : args.save_dir;

        std::cout << "OMP_THREAD_LIMIT=" << std::getenv("OMP_THREAD_LIMIT") << ", " << args.frames
                  << " frames per row after " << warm_up_frames << " warm-up frames; tesseract CLI "
                  << args.cli_runs << " runs; EAST: "
                  << (args.east_model.empty() ? "no rows (give --east-model "
                                                "frozen_east_text_detection.pb)"
                                              : args.east_model)
                  << "; DB: " << ocr::default_db_model_path() << "\n\n";
        std::cout
            << "| pipeline | scene | n | mean ms | rel std | median ms | precision | recall "
               "| CLI ms | CLI / pipeline | CLI as installed ms | CLI as installed / pipeline "
               "| bare API ms | pipeline / bare | thesis ms |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";

        for (const auto &scene : ocr::testdata::all_scenes()) {
            const std::string image_path = temp_dir + "/" + scene.name + ".png";
            cv::imwrite(image_path, scene.image);
            const ocr::Segmentation segmentation = segmentation_for(scene.name);

            // The bare call gets the gray frame ready-made: its time holds no conversion at all.
            cv::Mat gray;
            cv::cvtColor(scene.image, gray, cv::COLOR_BGR2GRAY);
            BareTesseract bare(segmentation);
            std::optional<FrameStats> bare_stats;
            const auto cli_stats =
                time_cli(image_path, segmentation, args.cli_runs, CliThreads::limited);
            const auto cli_openmp_stats =
                time_cli(image_path, segmentation, args.cli_runs, CliThreads::as_installed);

            std::vector<ocr::PipelineKind> kinds = {ocr::PipelineKind::pure,
                                                    ocr::PipelineKind::mser, ocr::PipelineKind::db};
            // The generated test network is no text detector: its figures are not EAST's.
            if (!args.east_model.empty())
                kinds.push_back(ocr::PipelineKind::east);
            for (const auto kind : kinds) {
                auto pipeline = ocr::make_pipeline(options_for(kind, scene, args));
                std::vector<ocr::TextBox> words;
                const auto run_pipeline = [&] { words = pipeline->recognise(scene.image); };
                FrameStats stats;
                if (kind == ocr::PipelineKind::pure) {
                    // PURE and the bare call do the same work: time them alternately.
                    std::tie(stats, bare_stats) =
                        ocr_bench_interleaved(args.frames, run_pipeline, [&] { bare.read(gray); });
                } else {
                    stats = time_frames(warm_up_frames, args.frames, run_pipeline);
                }
                const auto score = ocr::testdata::score_words(words, scene.words);
                const std::string name(ocr::to_string(kind));
                std::cout
                    << "| " << name << " | " << scene.name
                    << (kind == ocr::PipelineKind::pure &&
                                segmentation == ocr::Segmentation::sparse_text
                            ? "-sparse"
                            : "")
                    << " | " << stats.count << " | " << fixed(stats.mean_ms, 1) << " | "
                    << fixed(100.0 * stats.relative_std, 1) << "% | " << fixed(stats.median_ms, 1)
                    << " | " << fixed(score.precision(), 2) << " | " << fixed(score.recall(), 2)
                    << " | " << (cli_stats ? fixed(cli_stats->mean_ms, 1) : "n/a") << " | "
                    << (cli_stats ? fixed(cli_stats->mean_ms / stats.mean_ms, 2) + "x" : "n/a")
                    << " | " << (cli_openmp_stats ? fixed(cli_openmp_stats->mean_ms, 1) : "n/a")
                    << " | "
                    << (cli_openmp_stats ? fixed(cli_openmp_stats->mean_ms / stats.mean_ms, 2) + "x"
                                         : "n/a")
                    << " | " << fixed(bare_stats->mean_ms, 1) << " | "
                    << fixed(stats.mean_ms / bare_stats->mean_ms, 3) << "x | "
                    << (thesis_ms.count(name) != 0 ? fixed(thesis_ms.at(name).at(scene.name), 0)
                                                   : std::string("-"))
                    << " |" << std::endl;
                if (std::getenv("UBII_OCR_BENCH_VERBOSE") != nullptr)
                    std::cerr << name << " " << scene.name << ": " << ocr::testdata::describe(score)
                              << "\n";
            }
        }
        std::cout
            << "\nCLI and bare API use PURE's settings for the scene (automatic segmentation "
               "for baseline, sparse text for sign and webcam, "
            << source_resolution_dpi
            << " dpi); the CLI loads the model on every run, the bare API gets the gray frame "
               "ready-made. \"CLI\" runs with OMP_THREAD_LIMIT=1 like the pipelines; \"CLI as "
               "installed\" without it (OpenMP threads on every core). Thesis figures: "
               "i5-8265U, Python.\n";
        return 0;
    } catch (const std::exception &error) {
        std::cerr << "ocr_bench: " << error.what() << "\n";
        return 1;
    }
}
