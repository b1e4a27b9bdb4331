#include "ubii/ocr/pipeline_factory.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "option_checks.hpp"
#include "ubii/ocr/error.hpp"

namespace ubii::ocr
{
namespace
{

template <class... Handlers> struct Overloaded : Handlers... {
    using Handlers::operator()...;
};
template <class... Handlers> Overloaded(Handlers...) -> Overloaded<Handlers...>;

} // namespace

PipelineKind parse_pipeline_kind(std::string_view name)
{
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower == "pure")
        return PipelineKind::pure;
    if (lower == "mser")
        return PipelineKind::mser;
    if (lower == "east")
        return PipelineKind::east;
    if (lower == "db")
        return PipelineKind::db;
    throw InvalidArgument("unknown OCR pipeline '" + std::string(name) +
                          "' (pure, mser, east or db)");
}

std::string_view to_string(PipelineKind kind)
{
    switch (kind) {
    case PipelineKind::pure:
        return "pure";
    case PipelineKind::mser:
        return "mser";
    case PipelineKind::east:
        return "east";
    case PipelineKind::db:
        return "db";
    }
    return "unknown";
}

PipelineOptions default_options(PipelineKind kind)
{
    switch (kind) {
    case PipelineKind::mser:
        return MserOptions{};
    case PipelineKind::east:
        return EastOptions{};
    case PipelineKind::db:
        return DbOptions{};
    case PipelineKind::pure:
        break;
    }
    return PureOptions{};
}

PipelineKind kind_of(const PipelineOptions &options)
{
    return std::visit(Overloaded{[](const PureOptions &) { return PipelineKind::pure; },
                                 [](const MserOptions &) { return PipelineKind::mser; },
                                 [](const EastOptions &) { return PipelineKind::east; },
                                 [](const DbOptions &) { return PipelineKind::db; }},
                      options);
}

TesseractOptions &tesseract_options(PipelineOptions &options)
{
    return std::visit([](auto &chosen) -> TesseractOptions & { return chosen.tesseract; }, options);
}

void check_options(const PipelineOptions &options)
{
    std::visit([](const auto &chosen) { detail::check(chosen); }, options);
}

std::unique_ptr<Pipeline> make_pipeline(const PipelineOptions &options)
{
    return std::visit(Overloaded{[](const PureOptions &pure) -> std::unique_ptr<Pipeline> {
                                     return std::make_unique<PurePipeline>(pure);
                                 },
                                 [](const MserOptions &mser) -> std::unique_ptr<Pipeline> {
                                     return std::make_unique<MserPipeline>(mser);
                                 },
                                 [](const EastOptions &east) -> std::unique_ptr<Pipeline> {
                                     return std::make_unique<EastPipeline>(east);
                                 },
                                 [](const DbOptions &db) -> std::unique_ptr<Pipeline> {
                                     return std::make_unique<DbPipeline>(db);
                                 }},
                      options);
}

} // namespace ubii::ocr
