// environmentKnowledgeBaseInterface.h: the drop-in for the document's helper class
// (D5.4.2 §5 and appendix A; SPEC §12), built on ekb's loader.
//
// A program written for the robot's `Environment::EnvironmentKnowledgeBase` compiles
// unchanged against this header and links ekb::ekb; what it loads is what `ekb check`
// validated. It may include it as `environmentKnowledgeBaseInterface.h`,
// `utilities/environmentKnowledgeBaseInterface.h` (the document's) or
// `behaviorController/environmentKnowledgeBaseInterface.h` (the robot's): the two others
// include this one.
//
// Where the configuration is. The constructor reads the first of
//   <root>/config/environmentKnowledgeBaseConfiguration.ini                  (the document's)
//   <root>/behaviorController/config/environmentKnowledgeBaseConfiguration.ini   (the robot's)
//   <root>/behaviorController/include/utilities/config/environmentKnowledgeBaseConfiguration.ini
//                                                                        (the 2026-02 example's)
// that exists, <root> being the ROS package (under ROS: ROS_PACKAGE_NAME defined and
// <ros/ros.h> available; ros::package::getPath, else the package on ROS_PACKAGE_PATH), or
// without ROS the current folder. The knowledge base it names is in the data/ folder beside
// that config/ folder. EKB_CONFIG, when set, names the configuration instead. When none
// exists, the file is not loaded, and the message lists every path tried.
//
// A refused file. A file with an error is never loaded, in part or whole, and neither is a
// value the fixed-size types below cannot hold (a text of STRING_LENGTH bytes or more, more
// than MAX_NUMBER_OF_TOUR_LOCATIONS stops, more than MAX_CULTURE_KEYS culture words): it is
// never cut. The constructor then throws ekb::LoadError (a std::runtime_error; findings()
// has every finding, what() names the first error) and logs nothing itself:
//   - a program that catches it has the findings, and logs them as it likes, or with
//     Environment::EnvironmentKnowledgeBase::report(error), which logs as below;
//   - a program that does not (the document's, a node holding the object at namespace
//     scope, constructed before main) does not end with `terminate` and SIGABRT: the
//     terminate handler the constructor installs logs the findings, errors first, then one
//     fatal line that names the file and the commands that show and fix it, and ends the
//     program with exit status 1 (std::_Exit: no static destructor runs on a half-started
//     program). Under ROS through ROS_ERROR, ROS_WARN and ROS_FATAL, else on standard error:
//       data/environmentKnowledgeBaseInput.dat:34:1: error[key-case]: ...
//       data/environmentKnowledgeBaseInput.dat:3:1: warning[...]: ...
//       the environment knowledge base data/environmentKnowledgeBaseInput.dat was refused
//       (1 error, 9 warnings): `ekb check data/environmentKnowledgeBaseInput.dat` shows them,
//       `ekb fix data/environmentKnowledgeBaseInput.dat` fixes what it can
//     (one line). Any other exception goes on to the terminate handler there was before.
// Both dialects (robotLocation, robotLocationPose) load.
//
// Sizes. STRING_LENGTH, MAX_STRING_LENGTH, MAX_FILENAME_LENGTH and KEY_LENGTH are the
// document's (200, 200, 200, 100) unless defined before (on the compiler line:
// -DSTRING_LENGTH=600 for a program built for the 2026-04 header); the loader then refuses
// a text of STRING_LENGTH bytes or more (rule drop-in-string-length), and loads a shorter
// one whole. Every file of a program must see the same sizes, as with the document's header.
//
// The `2026-03` robot's KeyValueType has `char gestureArm[STRING_LENGTH]` after
// culturalKnowledge ("left", "right", or "" when the file gives none): define
// EKB_GESTURE_ARM to 1 before including this header (CMake: compile definition
// EKB_GESTURE_ARM=1) to get it. Without it, KeyValueType is the document's, as SPEC §12
// shows it.
//
// Like the robot's header, this one includes <stdio.h>, <string.h>, <stdlib.h>,
// <math.h> and <ctype.h>, and says `using namespace std;` (define
// EKB_NO_USING_NAMESPACE_STD to leave it out). The types and the class are in namespace
// Environment, and also named at global scope (as appendix A shows them), unless
// EKB_NO_GLOBAL_NAMES is defined. It needs C++17.
#ifndef ENVIRONMENT_KNOWLEDGE_BASE_INTERFACE_H
#define ENVIRONMENT_KNOWLEDGE_BASE_INTERFACE_H

#if (defined(_MSVC_LANG) ? _MSVC_LANG : __cplusplus) < 201703L
#error "environmentKnowledgeBaseInterface.h (ekb's drop-in) needs C++17 or later: g++ -std=c++17; CMake: link ekb::ekb (it asks for cxx_std_17), or set CXX_STANDARD 17"
#endif

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "ekb.hpp"

#if defined(ROS_PACKAGE_NAME) && defined(__has_include)
#if __has_include(<ros/ros.h>)
#define EKB_DROP_IN_ROS 1
#include <ros/ros.h>
#if __has_include(<ros/package.h>)
#define EKB_DROP_IN_ROSLIB 1
#include <ros/package.h>
#else
#include <fstream>
#include <sstream>
#endif
#endif
#endif

#ifndef EKB_NO_USING_NAMESPACE_STD
using namespace std;
#endif

#ifndef TRUE
#define TRUE 1
#endif
#ifndef FALSE
#define FALSE 0
#endif
// The document's sizes, unless the program chose its version's (the 2026-04 header:
// STRING_LENGTH, MAX_STRING_LENGTH and MAX_FILENAME_LENGTH 600, KEY_LENGTH 200).
#ifndef MAX_STRING_LENGTH
#define MAX_STRING_LENGTH 200
#endif
#ifndef MAX_FILENAME_LENGTH
#define MAX_FILENAME_LENGTH 200
#endif
#ifndef STRING_LENGTH
#define STRING_LENGTH 200
#endif
#ifndef KEY_LENGTH
#define KEY_LENGTH 100
#endif
#define MAX_CULTURE_KEYS 2
#define NUMBER_OF_CONFIGURATION_KEYS 3
#define NUMBER_OF_VALUE_KEYS 13
#define MAX_NUMBER_OF_TOUR_LOCATIONS 20

static_assert(STRING_LENGTH >= 2 && STRING_LENGTH <= 1048576,
              "STRING_LENGTH is the bytes of a text field, its NUL included: 2 to 1048576 (the document's is 200)");
static_assert(MAX_FILENAME_LENGTH >= 2 && KEY_LENGTH >= 2 && MAX_STRING_LENGTH >= 2,
              "MAX_FILENAME_LENGTH, KEY_LENGTH and MAX_STRING_LENGTH are sizes of text fields: 2 or more");

namespace Environment {

typedef char Keyword[KEY_LENGTH];

typedef struct {
    char knowledgeBase[MAX_FILENAME_LENGTH];
    bool verboseMode;
} ConfigurationDataType;

typedef struct {
    float x;
    float y;
    float theta;
} RobotLocationType;

typedef struct {
    float x;
    float y;
    float z;
} GestureTargetType;

typedef struct {
    int numberOfLocations;
    int locationIdNumber[MAX_NUMBER_OF_TOUR_LOCATIONS];
} TourSpecificationType;

typedef struct {
    char *key[MAX_CULTURE_KEYS];
    int numberOfKeys;
} CulturalKnowledgeType;

typedef struct {
    int key;  // the location's id
    RobotLocationType robotLocation;
    GestureTargetType gestureTarget;
    CulturalKnowledgeType culturalKnowledge;
#if defined(EKB_GESTURE_ARM) && EKB_GESTURE_ARM
    char gestureArm[STRING_LENGTH];
#endif
    char robotLocationDescription[STRING_LENGTH];
    char preGestureMessageEnglish[STRING_LENGTH];
    char preGestureMessageIsiZulu[STRING_LENGTH];
    char preGestureMessageKinyarwanda[STRING_LENGTH];
    char postGestureMessageEnglish[STRING_LENGTH];
    char postGestureMessageIsiZulu[STRING_LENGTH];
    char postGestureMessageKinyarwanda[STRING_LENGTH];
} KeyValueType;

class EnvironmentKnowledgeBase {
public:
    // Reads the configuration, then the knowledge base; throws ekb::LoadError if the file
    // has an error or cannot be read. Uncaught, it ends the program with the findings and
    // exit status 1 (see the top of this header).
    EnvironmentKnowledgeBase() {
        try {
            load(ekb::KnowledgeBase::configured(configurationPath(), dropInOptions()));
        } catch (const ekb::LoadError &) {
            installTerminateHandler();
            throw;
        }
    }

    ~EnvironmentKnowledgeBase() = default;

    // Its culture words' pointers point into this object: it is neither copied nor moved.
    EnvironmentKnowledgeBase(const EnvironmentKnowledgeBase &) = delete;
    EnvironmentKnowledgeBase &operator=(const EnvironmentKnowledgeBase &) = delete;

    // Copies the location with id `key` into `*keyValue`; false if there is none.
    bool getValue(int key, KeyValueType *keyValue) {
        if (keyValue == nullptr) return false;
        auto found = std::lower_bound(locations_.begin(), locations_.end(), key,
                                      [](const KeyValueType &location, int id) { return location.key < id; });
        if (found == locations_.end() || found->key != key) return false;
        *keyValue = *found;
        return true;
    }

    // Copies the tour into `*tour`; true if it has one or more stops.
    bool getTour(TourSpecificationType *tour) {
        if (tour == nullptr) return false;
        *tour = tour_;
        return tour_.numberOfLocations > 0;
    }

    // Prints every location, in id order, to standard output.
    void printToScreen() {
        for (const KeyValueType &location : locations_) {
            printf("Location %d: %s\n", location.key, location.robotLocationDescription);
            printf("  %-30s %s\n", "robotLocationDescription", location.robotLocationDescription);
            printf("  %-30s %g %g %g\n", "robotLocation", location.robotLocation.x, location.robotLocation.y,
                   location.robotLocation.theta);
            printf("  %-30s %g %g %g\n", "gestureTarget", location.gestureTarget.x, location.gestureTarget.y,
                   location.gestureTarget.z);
#if defined(EKB_GESTURE_ARM) && EKB_GESTURE_ARM
            printf("  %-30s %s\n", "gestureArm", location.gestureArm);
#endif
            printf("  %-30s %s\n", "preGestureMessageEnglish", location.preGestureMessageEnglish);
            printf("  %-30s %s\n", "preGestureMessageIsiZulu", location.preGestureMessageIsiZulu);
            printf("  %-30s %s\n", "preGestureMessageKinyarwanda", location.preGestureMessageKinyarwanda);
            printf("  %-30s %s\n", "postGestureMessageEnglish", location.postGestureMessageEnglish);
            printf("  %-30s %s\n", "postGestureMessageIsiZulu", location.postGestureMessageIsiZulu);
            printf("  %-30s %s\n", "postGestureMessageKinyarwanda", location.postGestureMessageKinyarwanda);
            printf("  %-30s", "culturalKnowledge");
            for (int word = 0; word < location.culturalKnowledge.numberOfKeys; ++word)
                printf(" %s", location.culturalKnowledge.key[word]);
            printf("\n\n");
        }
        printf("Tour: %d stops:", tour_.numberOfLocations);
        for (int stop = 0; stop < tour_.numberOfLocations; ++stop) printf(" %d", tour_.locationIdNumber[stop]);
        printf("\n");
        fflush(stdout);
    }

    // Logs what a refused or unreadable file's error says, as an uncaught one ends the
    // program: every finding, errors first (ROS_ERROR, ROS_WARN, ROS_INFO under ROS,
    // standard error otherwise), then one fatal line (ROS_FATAL) naming the file and
    // `ekb check FILE`, `ekb fix FILE`.
    static void report(const ekb::LoadError &error) {
        std::vector<const ekb::Finding *> findings;
        for (const ekb::Finding &finding : error.findings()) findings.push_back(&finding);
        std::stable_sort(findings.begin(), findings.end(), [](const ekb::Finding *a, const ekb::Finding *b) {
            return static_cast<int>(a->severity) < static_cast<int>(b->severity);
        });
        std::size_t errors = 0, warnings = 0;
        for (const ekb::Finding *finding : findings) {
            std::string line = finding->toString();
            if (finding->help) line += " (help: " + *finding->help + ")";
            log(finding->severity, line);
            if (finding->severity == ekb::Severity::error) ++errors;
            if (finding->severity == ekb::Severity::warning) ++warnings;
        }
        std::string fatal;
        if (findings.empty()) {
            fatal = std::string("the environment knowledge base was not loaded: ") + error.what();
        } else {
            const std::string &file = findings.front()->file;
            std::string quoted = shellWord(file);
            fatal = "the environment knowledge base " + file + " was refused (" + count(errors, "error") + ", " +
                    count(warnings, "warning") + "): `ekb check " + quoted + "` shows them, `ekb fix " + quoted +
                    "` fixes what it can";
        }
#ifdef EKB_DROP_IN_ROS
        ROS_FATAL("%s", fatal.c_str());
#else
        fprintf(stderr, "%s\n", fatal.c_str());
#endif
        fflush(stdout);
        fflush(stderr);
    }

private:
    // The configuration to read; nullopt: the one EKB_CONFIG names. Throws ekb::LoadError,
    // naming every path tried, when none of the layouts has one.
    static std::optional<std::string> configurationPath() {
        const char *named = getenv("EKB_CONFIG");
        if (named != nullptr && *named != '\0') return std::nullopt;
        std::string root;
        std::string where = "under the current folder";
#ifdef EKB_DROP_IN_ROS
        std::string package = packagePath(ROS_PACKAGE_NAME);
        if (!package.empty()) {
            root = package + "/";
            where = std::string("in the ROS package ") + ROS_PACKAGE_NAME;
        } else {
            ROS_WARN("package %s not found on ROS_PACKAGE_PATH: looking for the configuration under the current folder",
                     ROS_PACKAGE_NAME);
        }
#endif
        static const char *const layouts[] = {
            "config/",                                 // the document's (Figure 2)
            "behaviorController/config/",              // the robot's
            "behaviorController/include/utilities/config/",  // the 2026-02 example's
        };
        std::string tried;
        for (const char *layout : layouts) {
            std::string candidate = root + layout + "environmentKnowledgeBaseConfiguration.ini";
            std::error_code ignored;
            if (std::filesystem::exists(candidate, ignored)) return candidate;
            std::filesystem::path shown = std::filesystem::absolute(candidate, ignored);
            // The package's folder or the current one may have any name: shown as ekb shows one.
            tried += (tried.empty() ? "" : ", ") + ekb::shown(shown.empty() ? candidate : shown.string());
        }
        throw ekb::LoadError("no environmentKnowledgeBaseConfiguration.ini " + where + "; tried " + tried +
                                 " (EKB_CONFIG, not set, may name one)",
                             {}, true);
    }

    static std::string count(std::size_t n, const char *what) {
        return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
    }

    // `text` as one word of a POSIX shell command.
    static std::string shellWord(const std::string &text) {
        bool plain = !text.empty();
        for (char c : text)
            if (!isalnum(static_cast<unsigned char>(c)) && strchr("/._-+:@%,=", c) == nullptr) plain = false;
        if (plain) return text;
        std::string out = "'";
        for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return out + "'";
    }

    // Ends the program as a refused file should, when nothing catches the LoadError.
    [[noreturn]] static void onTerminate() {
        if (std::exception_ptr current = std::current_exception()) {
            try {
                std::rethrow_exception(current);
            } catch (const ekb::LoadError &error) {
                report(error);
                std::_Exit(1);
            } catch (...) {
            }
        }
        if (std::terminate_handler previous = previousTerminateHandler()) previous();
        std::abort();
    }

    static std::terminate_handler &previousTerminateHandler() {
        static std::terminate_handler previous = nullptr;
        return previous;
    }

    static void installTerminateHandler() {
        std::terminate_handler current = std::get_terminate();
        if (current == &EnvironmentKnowledgeBase::onTerminate) return;
        previousTerminateHandler() = current;
        std::set_terminate(&EnvironmentKnowledgeBase::onTerminate);
    }

#ifdef EKB_DROP_IN_ROS
    // The folder of the ROS package `name`: ros::package::getPath where roslib is, else the
    // folder on ROS_PACKAGE_PATH whose package.xml names it, as rospack finds it.
    static std::string packagePath(const std::string &name) {
#ifdef EKB_DROP_IN_ROSLIB
        return ros::package::getPath(name);
#else
        namespace fs = std::filesystem;
        auto names = [&name](const fs::path &folder) {
            std::ifstream file(folder / "package.xml");
            std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
            return text.find("<name>" + name + "</name>") != std::string::npos;
        };
        const char *roots = getenv("ROS_PACKAGE_PATH");
        std::stringstream paths(roots ? roots : "");
        std::string root;
        while (std::getline(paths, root, ':')) {
            std::error_code error;
            if (root.empty()) continue;
            if (fs::exists(fs::path(root) / "package.xml", error)) {
                if (names(root)) return root;
                continue;
            }
            fs::recursive_directory_iterator walk(root, fs::directory_options::skip_permission_denied, error), end;
            for (; !error && walk != end; walk.increment(error)) {
                if (!walk->is_directory(error)) continue;
                if (fs::exists(walk->path() / "CATKIN_IGNORE", error)) {
                    walk.disable_recursion_pending();
                    continue;
                }
                if (!fs::exists(walk->path() / "package.xml", error)) continue;
                walk.disable_recursion_pending();  // no package inside a package
                if (names(walk->path())) return walk->path().string();
            }
        }
        return std::string();
#endif
    }
#endif

    static ekb::Options dropInOptions() {
        ekb::Options options;
        options.fixedSizeLimits = true;
        options.stringLength = STRING_LENGTH;
        return options;
    }

    static void log(ekb::Severity severity, const std::string &line) {
#ifdef EKB_DROP_IN_ROS
        switch (severity) {
        case ekb::Severity::error: ROS_ERROR("%s", line.c_str()); break;
        case ekb::Severity::warning: ROS_WARN("%s", line.c_str()); break;
        default: ROS_INFO("%s", line.c_str()); break;
        }
#else
        (void)severity;
        fprintf(stderr, "%s\n", line.c_str());
#endif
    }

    // Copies `text` into a field of STRING_LENGTH bytes (the loader refused longer ones).
    static void copy(char (&field)[STRING_LENGTH], std::optional<std::string_view> text) {
        std::string_view value = text.value_or(std::string_view());
        std::size_t length = std::min(value.size(), static_cast<std::size_t>(STRING_LENGTH - 1));
        memcpy(field, value.data(), length);
        field[length] = '\0';
    }

    void load(const ekb::KnowledgeBase &kb) {
        std::vector<ekb::Location> locations = kb.locations();
        std::size_t wordCount = 0;
        for (const ekb::Location &location : locations) wordCount += location.culturalKnowledge.size();
        words_.reserve(wordCount);  // never reallocated: KeyValueType points into it
        locations_.reserve(locations.size());
        for (const ekb::Location &location : locations) {
            KeyValueType value;
            memset(&value, 0, sizeof value);
            value.key = static_cast<int>(location.id);
            if (location.pose)
                value.robotLocation = RobotLocationType{static_cast<float>(location.pose->x),
                                                        static_cast<float>(location.pose->y),
                                                        static_cast<float>(location.pose->theta)};
            if (location.gestureTarget)
                value.gestureTarget = GestureTargetType{static_cast<float>(location.gestureTarget->x),
                                                        static_cast<float>(location.gestureTarget->y),
                                                        static_cast<float>(location.gestureTarget->z)};
            for (std::string_view word : location.culturalKnowledge) {
                if (value.culturalKnowledge.numberOfKeys == MAX_CULTURE_KEYS) break;  // refused by the loader
                words_.emplace_back(word);
                value.culturalKnowledge.key[value.culturalKnowledge.numberOfKeys++] = &words_.back()[0];
            }
#if defined(EKB_GESTURE_ARM) && EKB_GESTURE_ARM
            if (location.gestureArm)
                copy(value.gestureArm, *location.gestureArm == ekb::Arm::left ? "left" : "right");
#endif
            copy(value.robotLocationDescription, location.description);
            copy(value.preGestureMessageEnglish, location.preGestureMessage.english);
            copy(value.preGestureMessageIsiZulu, location.preGestureMessage.isiZulu);
            copy(value.preGestureMessageKinyarwanda, location.preGestureMessage.kinyarwanda);
            copy(value.postGestureMessageEnglish, location.postGestureMessage.english);
            copy(value.postGestureMessageIsiZulu, location.postGestureMessage.isiZulu);
            copy(value.postGestureMessageKinyarwanda, location.postGestureMessage.kinyarwanda);
            locations_.push_back(value);
        }
        memset(&tour_, 0, sizeof tour_);
        for (std::uint32_t stop : kb.tour()) {
            if (tour_.numberOfLocations == MAX_NUMBER_OF_TOUR_LOCATIONS) break;  // refused by the loader
            tour_.locationIdNumber[tour_.numberOfLocations++] = static_cast<int>(stop);
        }
    }

    std::vector<KeyValueType> locations_;  // in ascending id order
    TourSpecificationType tour_;
    std::vector<std::string> words_;  // the culture words the locations point to
};

}  // namespace Environment

#ifndef EKB_NO_GLOBAL_NAMES
using Environment::ConfigurationDataType;
using Environment::CulturalKnowledgeType;
using Environment::EnvironmentKnowledgeBase;
using Environment::GestureTargetType;
using Environment::KeyValueType;
using Environment::Keyword;
using Environment::RobotLocationType;
using Environment::TourSpecificationType;
#endif

#endif  // ENVIRONMENT_KNOWLEDGE_BASE_INTERFACE_H
