// OCR evaluation: every pipeline, and the tesseract command-line tool as installed, on the
// evaluation set (ocr/testing/evaluation_set.hpp: 36 generated images the pipelines were never
// tuned on), scored word by word against the ground truth: precision / recall per scene kind and
// over all images (summed), and the mean time per image. Prints a Markdown table; asserts nothing.
//
//   ocr_eval [--pipelines pure,pure-auto,mser,db,cli-sparse,cli-auto] [--east-model PATH]
//            [--save DIR] [--verbose]
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <unistd.h>

#include "evaluation_set.hpp"
#include "ubii/ocr/ocr.hpp"

namespace
{

namespace ocr = ubii::ocr;
namespace data = ubii::ocr::testdata;
using Clock = std::chrono::steady_clock;

struct Arguments {
    std::vector<std::string> pipelines = {"pure", "pure-auto",  "mser",
                                          "db",   "cli-sparse", "cli-auto"};
    std::string east_model;
    std::string save_dir;
    bool verbose = false;
};

std::vector<std::string> split(const std::string &text, char separator)
{
    std::vector<std::string> parts;
    std::istringstream stream(text);
    for (std::string part; std::getline(stream, part, separator);)
        if (!part.empty())
            parts.push_back(part);
    return parts;
}

Arguments parse(int argc, char **argv)
{
    Arguments args;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--verbose") {
            args.verbose = true;
            continue;
        }
        if (i + 1 >= argc)
            throw ocr::InvalidArgument(flag + " wants a value");
        const std::string value = argv[++i];
        if (flag == "--pipelines")
            args.pipelines = split(value, ',');
        else if (flag == "--east-model")
            args.east_model = value;
        else if (flag == "--save")
            args.save_dir = value;
        else
            throw ocr::InvalidArgument("unknown option " + flag);
    }
    if (!args.east_model.empty())
        args.pipelines.push_back("east");
    return args;
}

// How one row reads an image: a pipeline of ours, or the tesseract CLI.
class Reader
{
  public:
    virtual ~Reader() = default;
    virtual std::vector<ocr::TextBox> read(const cv::Mat &image) = 0;
};

class PipelineReader final : public Reader
{
  public:
    explicit PipelineReader(const ocr::PipelineOptions &options)
        : pipeline_(ocr::make_pipeline(options))
    {
    }
    std::vector<ocr::TextBox> read(const cv::Mat &image) override
    {
        return pipeline_->recognise(image);
    }

  private:
    std::unique_ptr<ocr::Pipeline> pipeline_;
};

// `tesseract FILE stdout --psm N tsv` as installed (its own OpenMP threads), words with
// confidence >= 70 as the pipelines' default minimum. LC_ALL=C: its TSV numbers follow the locale.
class CliReader final : public Reader
{
  public:
    CliReader(int psm, std::string dir) : psm_(psm), dir_(std::move(dir))
    {
    }
    std::vector<ocr::TextBox> read(const cv::Mat &image) override
    {
        const std::string path = dir_ + "/cli_input.png";
        cv::imwrite(path, image);
        const std::string command = "env -u OMP_THREAD_LIMIT LC_ALL=C " UBII_TESSERACT_CLI " " +
                                    path + " stdout --psm " + std::to_string(psm_) +
                                    " tsv 2>/dev/null";
        std::vector<ocr::TextBox> words;
        FILE *pipe = popen(command.c_str(), "r");
        if (pipe == nullptr)
            throw std::runtime_error("cannot run " + command);
        std::array<char, 4096> line{};
        while (std::fgets(line.data(), line.size(), pipe) != nullptr) {
            const auto fields = split_tsv(line.data());
            if (fields.size() < 12 || fields[0] != "5")
                continue;
            const float confidence = std::strtof(fields[10].c_str(), nullptr);
            std::string text = fields[11];
            while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
                text.pop_back();
            if (confidence < 70.0f || text.empty())
                continue;
            words.push_back({text, confidence,
                             cv::Rect(std::stoi(fields[6]), std::stoi(fields[7]),
                                      std::stoi(fields[8]), std::stoi(fields[9])),
                             std::nullopt});
        }
        pclose(pipe);
        return words;
    }

  private:
    static std::vector<std::string> split_tsv(const std::string &line)
    {
        std::vector<std::string> fields;
        std::size_t start = 0;
        for (std::size_t tab; (tab = line.find('\t', start)) != std::string::npos; start = tab + 1)
            fields.push_back(line.substr(start, tab - start));
        fields.push_back(line.substr(start));
        return fields;
    }
    int psm_;
    std::string dir_;
};

std::unique_ptr<Reader> make_reader(const std::string &name, const Arguments &args,
                                    const std::string &dir)
{
    if (name == "cli-sparse")
        return std::make_unique<CliReader>(11, dir);
    if (name == "cli-auto")
        return std::make_unique<CliReader>(3, dir);
    if (name == "pure" || name == "pure-auto") {
        auto options = ocr::default_options(ocr::PipelineKind::pure);
        ocr::tesseract_options(options).segmentation =
            name == "pure" ? ocr::Segmentation::sparse_text : ocr::Segmentation::automatic;
        return std::make_unique<PipelineReader>(options);
    }
    // A pipeline that needs more than its defaults gets it here.
    auto options = ocr::default_options(ocr::parse_pipeline_kind(name));
    if (auto *east = std::get_if<ocr::EastOptions>(&options))
        east->model_path = args.east_model;
    return std::make_unique<PipelineReader>(options);
}

std::string fixed(double value, int digits)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(digits) << value;
    return text.str();
}

std::string cell(const data::WordScore &score)
{
    return fixed(score.precision(), 2) + " / " + fixed(score.recall(), 2);
}

void add(data::WordScore &sum, const data::WordScore &score)
{
    sum.correct += score.correct;
    sum.recognised += score.recognised;
    sum.expected += score.expected;
}

} // namespace

int main(int argc, char **argv)
{
    ocr::ensure_single_omp_thread(argc, argv);
    try {
        const Arguments args = parse(argc, argv);
        char temp_template[] = "/tmp/ocr_eval.XXXXXX";
        const std::string dir = args.save_dir.empty() ? mkdtemp(temp_template) : args.save_dir;
        if (!args.save_dir.empty())
            data::write_evaluation_set(args.save_dir);
        const auto set = data::evaluation_set();
        std::size_t words = 0;
        for (const auto &entry : set)
            words += entry.scene.words.size();
        std::cout
            << set.size() << " evaluation images (seed 0x" << std::hex << data::kUbiiEvaluationSeed
            << std::dec << "), " << words
            << " words; precision / recall, summed over the images of each kind\n\n| reader |";
        for (const auto &kind : data::evaluation_kinds())
            std::cout << ' ' << kind << " |";
        std::cout << " all | mean ms |\n|---|";
        for (std::size_t i = 0; i <= data::evaluation_kinds().size() + 1; ++i)
            std::cout << "---|";
        std::cout << '\n';
        for (const std::string &name : args.pipelines) {
            const auto reader = make_reader(name, args, dir);
            std::map<std::string, data::WordScore> per_kind;
            data::WordScore all;
            double total_ms = 0;
            for (const auto &entry : set) {
                const auto began = Clock::now();
                const auto found = reader->read(entry.scene.image);
                total_ms += std::chrono::duration<double, std::milli>(Clock::now() - began).count();
                const auto score = data::score_words(found, entry.scene.words);
                add(per_kind[entry.kind], score);
                add(all, score);
                if (args.verbose)
                    std::cerr << name << " " << entry.scene.name << ": " << data::describe(score)
                              << "\n";
            }
            std::cout << "| " << name << " |";
            for (const auto &kind : data::evaluation_kinds())
                std::cout << ' ' << cell(per_kind[kind]) << " |";
            std::cout << ' ' << cell(all) << " | " << fixed(total_ms / static_cast<double>(set.size()), 0) << " |"
                      << std::endl;
        }
        std::cout << "\npure: sparse-text segmentation (the module's default); pure-auto: "
                     "automatic; cli-*: the tesseract command as installed (OpenMP threads), "
                     "--psm 11 / 3, words of confidence >= 70. Times include the CLI's model "
                     "load on every image.\n";
        return 0;
    } catch (const std::exception &error) {
        std::cerr << "ocr_eval: " << error.what() << "\n";
        return 1;
    }
}
