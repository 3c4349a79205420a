// ekb's C++17 API (SPEC §12): a knowledge base as `ekb export` shows it, or an
// ekb::LoadError carrying `ekb check`'s findings. Header-only, over the C ABI of ekb.h;
// link ekb::ekb (CMake: find_package(ekb CONFIG REQUIRED)).
//
//   ekb::KnowledgeBase kb = ekb::KnowledgeBase::open("data/environmentKnowledgeBaseInput.dat");
//   for (std::uint32_t id : kb.tour())
//       std::cout << kb.location(id)->description.value_or("") << '\n';
//
// Texts are std::string_view into the knowledge base: valid while the KnowledgeBase lives.
// Any number of threads may read one KnowledgeBase at once.
#ifndef EKB_HPP
#define EKB_HPP

#if (defined(_MSVC_LANG) ? _MSVC_LANG : __cplusplus) < 201703L
#error "ekb.hpp needs C++17 or later: g++/clang++ -std=c++17; CMake: link ekb::ekb (it asks for cxx_std_17), or set CXX_STANDARD 17"
#endif

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ekb.h"

namespace ekb {

enum class Severity { error, warning, info };

// "error", "warning" or "info", as `ekb check` writes them.
inline std::string_view severity_name(Severity severity) {
    switch (severity) {
    case Severity::error: return "error";
    case Severity::warning: return "warning";
    default: return "info";
    }
}

// One finding of `ekb check`: 1-based lines and columns (in Unicode scalar values).
struct Finding {
    std::string file;
    std::string rule;
    Severity severity;
    std::string message;
    std::optional<std::string> help;
    std::uint32_t line;
    std::uint32_t column;
    std::uint32_t endLine;
    std::uint32_t endColumn;
    std::optional<std::uint32_t> locationId;

    // `file:line:column: severity[rule]: message`, as `ekb check --format concise`.
    std::string toString() const {
        return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
               std::string(severity_name(severity)) + "[" + rule + "]: " + message;
    }
};

// A call into the C ABI failed for a reason other than the file (a bug of the caller or
// of ekb): its status.
class Error : public std::logic_error {
public:
    Error(const char *call, ekb_status status)
        : std::logic_error(std::string(call) + ": " + name(status)), status_(status) {}
    ekb_status status() const noexcept { return status_; }

private:
    static std::string name(ekb_status status) {
        ekb_str text = ekb_status_name(static_cast<std::int32_t>(status));
        return std::string(text.ptr, text.len);
    }
    ekb_status status_;
};

// The knowledge base was not loaded: the file has an error (every finding of the check is
// here, errors first, a consequence after its cause), or it could not be read (no
// findings).
// what() names the first error and how many there are.
class LoadError : public std::runtime_error {
public:
    LoadError(const std::string &what, std::vector<Finding> findings, bool unreadable)
        : std::runtime_error(what), findings_(std::move(findings)), unreadable_(unreadable) {}
    const std::vector<Finding> &findings() const noexcept { return findings_; }
    // The file or its configuration could not be read (rather than refused).
    bool unreadable() const noexcept { return unreadable_; }

private:
    std::vector<Finding> findings_;
    bool unreadable_;
};

struct Pose {
    double x, y, theta;
};

struct Point {
    double x, y, z;
};

enum class Arm { left, right };

// One message in the three languages; a language the file does not give is nullopt.
struct Messages {
    std::optional<std::string_view> english, isiZulu, kinyarwanda;
};

// One location, as `ekb export` shows it: a field absent from the file is nullopt.
struct Location {
    std::uint32_t id;
    std::optional<std::string_view> description;
    std::optional<Pose> pose;
    std::optional<Point> gestureTarget;
    std::optional<Arm> gestureArm;
    Messages preGestureMessage;
    Messages postGestureMessage;
    std::vector<std::string_view> culturalKnowledge;
};

// How a file is checked before it is loaded.
struct Options {
    // The robot's reader to check against ("2025-06", ...); empty: as `ekb check` chooses.
    std::string reader;
    // Refuse values the document's fixed-size types cannot hold (the drop-in class).
    bool fixedSizeLimits = false;
    // Read no project settings, not even settingsPath's (for programs written when an
    // ekb.toml above the file was read).
    bool isolated = false;
    // With fixedSizeLimits: the STRING_LENGTH of those types, its NUL included (the
    // program's: 600 for the 2026-04 header); 0: the document's 200. Else 2 to 1048576.
    std::size_t stringLength = 0;
    // The project settings (ekb.toml) to check with, by path; empty: none. The loader reads
    // no settings it is not asked for: an ekb.toml above the file changes nothing.
    std::string settingsPath;
};

namespace detail {

inline std::optional<std::string_view> view(ekb_str text) {
    if (text.ptr == nullptr) return std::nullopt;
    return std::string_view(text.ptr, text.len);
}

inline std::string owned(ekb_str text) { return text.ptr ? std::string(text.ptr, text.len) : std::string(); }

inline void expect(ekb_status status, const char *call) {
    if (status != EKB_OK) throw Error(call, status);
}

inline ekb_str str(std::string_view text) { return ekb_str{text.data(), text.size()}; }

}  // namespace detail

// `text` as every message of ekb shows a value: control and invisible characters escaped,
// cut after 300 characters; for a program's own messages about paths it did not write.
inline std::string shown(std::string_view text) {
    std::size_t needed = 0;
    detail::expect(ekb_shown(text.data(), text.size(), nullptr, 0, &needed), "ekb_shown");
    std::string out(needed, '\0');
    detail::expect(ekb_shown(text.data(), text.size(), out.data(), out.size(), &needed), "ekb_shown");
    return out;
}

namespace detail {

inline ekb_options options(const Options &options) {
    if (options.stringLength == 1 || options.stringLength > (std::size_t(1) << 20))
        throw std::invalid_argument("ekb::Options::stringLength is " + std::to_string(options.stringLength) +
                                    ": a STRING_LENGTH is 2 to 1048576 bytes (0: the document's 200)");
    ekb_options out{};
    out.reader = options.reader.empty() ? ekb_str{nullptr, 0} : str(options.reader);
    out.fixed_size_limits = options.fixedSizeLimits;
    out.isolated = options.isolated;
    out.settings_path = options.settingsPath.empty() ? ekb_str{nullptr, 0} : str(options.settingsPath);
    out.string_length = options.stringLength;
    return out;
}

inline std::vector<Finding> findings(ekb_handle handle) {
    std::size_t count = 0;
    expect(ekb_finding_count(handle, &count), "ekb_finding_count");
    std::vector<Finding> out;
    out.reserve(count);
    for (std::size_t index = 0; index < count; ++index) {
        ekb_finding f{};
        expect(ekb_finding_at(handle, index, &f), "ekb_finding_at");
        std::optional<std::string> help;
        if (f.help.ptr) help = owned(f.help);
        std::optional<std::uint32_t> location;
        if (f.location_id != 0) location = f.location_id;
        out.push_back(Finding{owned(f.file), owned(f.rule), static_cast<Severity>(f.severity), owned(f.message),
                              std::move(help), f.line, f.column, f.end_line, f.end_column, location});
    }
    return out;
}

inline Messages messages(const ekb_messages &m) { return Messages{view(m.english), view(m.isi_zulu), view(m.kinyarwanda)}; }

}  // namespace detail

class KnowledgeBase {
public:
    // Loads the file at `path`, or throws LoadError.
    static KnowledgeBase open(std::string_view path, const Options &options = {}) {
        ekb_options o = detail::options(options);
        ekb_handle handle = 0;
        ekb_status status = ekb_open_path(path.data(), path.size(), &o, &handle);
        return KnowledgeBase(handle, status, "ekb_open_path");
    }

    // Loads `data`, the content of a file called `name`, or throws LoadError.
    static KnowledgeBase fromBuffer(std::string_view name, std::string_view data, const Options &options = {}) {
        ekb_options o = detail::options(options);
        ekb_handle handle = 0;
        ekb_status status = ekb_open_buffer(name.data(), name.size(), reinterpret_cast<const std::uint8_t *>(data.data()),
                                            data.size(), &o, &handle);
        return KnowledgeBase(handle, status, "ekb_open_buffer");
    }

    // Loads the knowledge base a configuration names, as the robot's class does: the
    // configuration at `config`, or with none, EKB_CONFIG, else
    // config/environmentKnowledgeBaseConfiguration.ini under the current folder.
    static KnowledgeBase configured(std::optional<std::string_view> config = std::nullopt,
                                    const Options &options = {}) {
        ekb_options o = detail::options(options);
        ekb_handle handle = 0;
        ekb_status status = config ? ekb_open_configured(config->data(), config->size(), &o, &handle)
                                   : ekb_open_configured(nullptr, 0, &o, &handle);
        return KnowledgeBase(handle, status, "ekb_open_configured");
    }

    KnowledgeBase(KnowledgeBase &&other) noexcept : handle_(std::exchange(other.handle_, 0)) {}
    KnowledgeBase &operator=(KnowledgeBase &&other) noexcept {
        if (this != &other) {
            release();
            handle_ = std::exchange(other.handle_, 0);
        }
        return *this;
    }
    KnowledgeBase(const KnowledgeBase &) = delete;
    KnowledgeBase &operator=(const KnowledgeBase &) = delete;
    ~KnowledgeBase() { release(); }

    // The location with this id.
    std::optional<Location> location(std::uint32_t id) const {
        ekb_location found{};
        ekb_status status = ekb_location_by_id(handle_, id, &found);
        if (status == EKB_UNKNOWN_ID) return std::nullopt;
        detail::expect(status, "ekb_location_by_id");
        return convert(found);
    }

    // Every location, in ascending id order.
    std::vector<Location> locations() const {
        std::size_t count = 0;
        detail::expect(ekb_location_count(handle_, &count), "ekb_location_count");
        std::vector<Location> out;
        out.reserve(count);
        for (std::size_t index = 0; index < count; ++index) {
            ekb_location found{};
            detail::expect(ekb_location_at(handle_, index, &found), "ekb_location_at");
            out.push_back(convert(found));
        }
        return out;
    }

    // How many locations there are.
    std::size_t size() const {
        std::size_t count = 0;
        detail::expect(ekb_location_count(handle_, &count), "ekb_location_count");
        return count;
    }

    // The ids of the tour's stops, in the order visited.
    std::vector<std::uint32_t> tour() const {
        const std::uint32_t *stops = nullptr;
        std::size_t count = 0;
        detail::expect(ekb_tour(handle_, &stops, &count), "ekb_tour");
        if (count == 0) return {};
        return std::vector<std::uint32_t>(stops, stops + count);
    }

    // The warnings and notes of the check (a loaded file has no error).
    std::vector<Finding> findings() const { return detail::findings(handle_); }

    // The reader the file was checked against, e.g. "2025-06".
    std::string_view reader() const {
        ekb_str name{};
        detail::expect(ekb_reader(handle_, &name), "ekb_reader");
        return detail::view(name).value_or(std::string_view());
    }

    // The C handle, for calls of ekb.h; it stays owned by this object.
    ekb_handle handle() const noexcept { return handle_; }

private:
    KnowledgeBase(ekb_handle handle, ekb_status status, const char *call) : handle_(handle) {
        if (status == EKB_OK) return;
        if (status != EKB_REFUSED && status != EKB_UNREADABLE) {
            release();
            throw Error(call, status);
        }
        ekb_str message{};
        ekb_error_message(handle_, &message);
        std::string what = detail::owned(message);
        std::vector<Finding> findings = detail::findings(handle_);
        release();
        throw LoadError(what, std::move(findings), status == EKB_UNREADABLE);
    }

    Location convert(const ekb_location &found) const {
        Location out{found.id, detail::view(found.description), std::nullopt, std::nullopt, std::nullopt,
                     detail::messages(found.pre_gesture_message), detail::messages(found.post_gesture_message), {}};
        if (found.has_pose) out.pose = Pose{found.pose.x, found.pose.y, found.pose.theta};
        if (found.has_gesture_target)
            out.gestureTarget = Point{found.gesture_target.x, found.gesture_target.y, found.gesture_target.z};
        if (found.gesture_arm == EKB_ARM_LEFT) out.gestureArm = Arm::left;
        if (found.gesture_arm == EKB_ARM_RIGHT) out.gestureArm = Arm::right;
        out.culturalKnowledge.reserve(found.cultural_knowledge_count);
        for (std::size_t index = 0; index < found.cultural_knowledge_count; ++index) {
            ekb_str word{};
            detail::expect(ekb_cultural_word(handle_, found.id, index, &word), "ekb_cultural_word");
            out.culturalKnowledge.push_back(std::string_view(word.ptr, word.len));
        }
        return out;
    }

    void release() noexcept {
        if (handle_ != 0) ekb_free(handle_);
        handle_ = 0;
    }

    ekb_handle handle_;
};

}  // namespace ekb

#endif  // EKB_HPP
