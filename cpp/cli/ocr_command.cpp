// `ubii-node ocr FILE...`: reads the text in image files with an OCR processing module, locally,
// without a master. It runs the very module a session would (from the OCR plugin, through a
// Scheduler of its own), so what it prints is what a session's subscribers would receive.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "cli_error.hpp"
#include "commands.hpp"
#include "image_file.hpp"
#include "message_output.hpp"
#include "module_loading.hpp"

namespace ubii::cli
{

namespace
{

const std::map<std::string, std::string> &modules_by_pipeline()
{
    static const std::map<std::string, std::string> names = {{"pure", "TesseractOCR_PURE"},
                                                             {"mser", "TesseractOCR_MSER"},
                                                             {"east", "TesseractOCR_EAST"},
                                                             {"db", "TextDetection_DB"}};
    return names;
}

struct OcrOptions {
    std::vector<std::string> files;
    std::string pipeline = "pure";
    std::vector<std::string> arguments; // key=value for the chosen module
    ModuleOptions modules;
    bool json = false;
    double timeout_s = 60;
};

// What one pass of the module gave back.
struct FrameResult {
    std::optional<ubii::Object2DList> objects;
    std::string error;
};

// The module run here, on the files' images; its passes run on the module's worker thread.
class LocalModule
{
  public:
    // `verbose`: the lines the module logs (Tesseract's own chatter) go to stderr.
    LocalModule(std::unique_ptr<ubii::ProcessingModule> module, bool verbose)
        : module_(std::move(module))
    {
        ubii::Scheduler &scheduler = module_.scheduler();
        scheduler.on_output([this](const ubii::ProcessingModule &, const ubii::PassOutput &output) {
            if (const auto *objects = output.value.get_if<ubii::Object2DList>())
                result_.objects = *objects;
            else if (const auto *text = output.value.get_if<std::string>())
                result_.error = *text;
            return ubii::Status::ok;
        });
        if (verbose)
            scheduler.on_log([](const ubii::ProcessingModule &source, std::string_view line) {
                std::cerr << "ubii-node: " << source.name() << ": " << line << '\n';
            });
        scheduler.on_error([this](ubii::Status, std::string_view detail) {
            if (result_.error.empty())
                result_.error = std::string(detail);
        });
    }

    // One frame through the module: nothing if no pass ended within `timeout`.
    std::optional<FrameResult> read(ubii::Image2D image, std::chrono::duration<double> timeout)
    {
        result_ = {};
        module_.feed("image",
                     std::make_shared<const ubii::Record>("image", ubii::Value(std::move(image))));
        // An OCR module answers every frame with objects or an error record.
        if (!module_.run_until([this] { return result_.objects || !result_.error.empty(); },
                               std::chrono::duration_cast<std::chrono::nanoseconds>(timeout)))
            return std::nullopt;
        return result_;
    }

  private:
    FrameResult result_;
    ubii::StandaloneModule module_;
};

struct Word {
    std::string text;
    double left = 0, top = 0, width = 0, height = 0;
    double confidence = 0;
};

std::vector<Word> words_of(const ubii::Object2DList &objects)
{
    std::vector<Word> words;
    for (const auto &object : objects.elements()) {
        Word word{object.id(),
                  object.pose().position().x(),
                  object.pose().position().y(),
                  object.size().x(),
                  object.size().y(),
                  0};
        const auto user_data = nlohmann::json::parse(object.user_data_json(), nullptr, false);
        if (user_data.is_object() && user_data.contains("confidence") &&
            user_data["confidence"].is_number())
            word.confidence = user_data["confidence"].get<double>();
        words.push_back(std::move(word));
    }
    return words;
}

void print_text(const std::string &file, const std::vector<Word> &words, double ms)
{
    std::printf("%s: %zu words, %.0f ms\n", file.c_str(), words.size(), ms);
    for (const auto &word : words)
        std::printf("  %-24s %5.0f,%-5.0f %4.0fx%-4.0f %3.0f\n", ("\"" + word.text + "\"").c_str(),
                    word.left, word.top, word.width, word.height, word.confidence);
}

void print_json(const std::string &file, const std::string &module, const std::vector<Word> &words,
                double ms)
{
    nlohmann::ordered_json line = {{"file", file}, {"module", module}, {"ms", ms}};
    line["words"] = nlohmann::ordered_json::array();
    for (const auto &word : words)
        line["words"].push_back({{"text", word.text},
                                 {"box", {word.left, word.top, word.width, word.height}},
                                 {"confidence", word.confidence}});
    std::cout << line.dump() << std::endl;
}

std::unique_ptr<LocalModule> start_module(OcrOptions &options, const std::string &module,
                                          bool verbose)
{
    for (const std::string &argument : options.arguments)
        options.modules.arguments.push_back(module + ":" + argument);
    LoadedModules loaded = load_modules(options.modules, {module});
    try {
        return std::make_unique<LocalModule>(loaded.registry.create(module), verbose);
    } catch (const std::exception &error) {
        throw CliError(exit_modules, module + " could not start: " + error.what());
    }
}

int recognise_files(OcrOptions &options, int verbosity)
{
    const std::string module = modules_by_pipeline().at(options.pipeline);
    // Read every file first: a typo in the last name should not wait for the model to load.
    std::vector<ubii::Image2D> images;
    for (const std::string &file : options.files)
        images.push_back(read_image_file(file));
    const auto local = start_module(options, module, verbosity > 0);
    int failed = 0;
    for (std::size_t i = 0; i < images.size(); ++i) {
        const auto started = std::chrono::steady_clock::now();
        const auto result =
            local->read(std::move(images[i]), std::chrono::duration<double>(options.timeout_s));
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
                .count();
        if (!result)
            throw CliError(exit_timeout, options.files[i] + ": no result within " +
                                             std::to_string(options.timeout_s) + " s");
        if (!result->objects) {
            std::cerr << "ubii-node: " << options.files[i] << ": " << result->error << '\n';
            ++failed;
            continue;
        }
        const std::vector<Word> words = words_of(*result->objects);
        if (options.json)
            print_json(options.files[i], module, words, ms);
        else
            print_text(options.files[i], words, ms);
    }
    return failed > 0 ? exit_master_error : exit_ok;
}

} // namespace

void add_ocr_command(CLI::App &app, Context &context)
{
    CLI::App *command = app.add_subcommand(
        "ocr", "Read the text in image files with an OCR processing module, here, without a "
               "master: the words with their boxes (left,top widthxheight) and confidences");
    auto options = std::make_shared<OcrOptions>();
    command->add_option("FILE", options->files, "image files (anything OpenCV reads)")->required();
    command
        ->add_option("--pipeline", options->pipeline,
                     "pure (TesseractOCR_PURE), mser (TesseractOCR_MSER), east "
                     "(TesseractOCR_EAST: needs --arg model=frozen_east_text_detection.pb) or db "
                     "(TextDetection_DB: scripts/ocr-models.sh fetches its model)")
        ->check(CLI::IsMember({"pure", "mser", "east", "db"}))
        ->capture_default_str();
    command
        ->add_option("--arg", options->arguments,
                     "key=value for the module (lang, psm, min_confidence, model, input_size, ...: "
                     "`ubii-node modules` lists them); repeatable")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    command->add_flag("--json", options->json,
                      "one JSON object per file (-v: Tesseract's own messages on stderr)");
    command->add_option("--timeout", options->timeout_s, "seconds to wait for each file's result")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    add_module_options(*command, options->modules);
    command->callback([&context, options] {
        context.action = [&context, options] {
            return recognise_files(*options, context.verbosity);
        };
    });
}

} // namespace ubii::cli
