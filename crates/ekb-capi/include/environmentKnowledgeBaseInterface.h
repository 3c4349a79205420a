// environmentKnowledgeBaseInterface.h: the drop-in for the document's helper class
// (D5.4.2 §5 and appendix A; SPEC §12), built on ekb's loader.
//
// A program written for the robot's `Environment::EnvironmentKnowledgeBase` compiles
// unchanged against this header and links ekb::ekb; what it loads is what `ekb check`
// validated. The constructor reads the configuration as the robot's class does:
//   - under ROS (ROS_PACKAGE_NAME defined and <ros/package.h> available):
//     `ros::package::getPath(ROS_PACKAGE_NAME)/config/environmentKnowledgeBaseConfiguration.ini`,
//     the knowledge base in the package's data/ folder;
//   - otherwise the configuration that EKB_CONFIG names, else
//     config/environmentKnowledgeBaseConfiguration.ini under the current folder.
// A file with an error is never loaded, in part or whole: the constructor logs every
// finding (ROS_ERROR/ROS_WARN under ROS, standard error otherwise) with file, line, column
// and rule, and throws ekb::LoadError, whose what() names the first error. So is a value
// that the fixed-size types below cannot hold (a text of STRING_LENGTH bytes or more, more
// than MAX_NUMBER_OF_TOUR_LOCATIONS stops, more than MAX_CULTURE_KEYS culture words): it is
// never cut. Both dialects (robotLocation, robotLocationPose) load.
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
// EKB_NO_GLOBAL_NAMES is defined.
#ifndef ENVIRONMENT_KNOWLEDGE_BASE_INTERFACE_H
#define ENVIRONMENT_KNOWLEDGE_BASE_INTERFACE_H

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <algorithm>
#include <cstdint>
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
#include <filesystem>
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
#define MAX_STRING_LENGTH 200
#define MAX_FILENAME_LENGTH 200
#define STRING_LENGTH 200
#define KEY_LENGTH 100
#define MAX_CULTURE_KEYS 2
#define NUMBER_OF_CONFIGURATION_KEYS 3
#define NUMBER_OF_VALUE_KEYS 13
#define MAX_NUMBER_OF_TOUR_LOCATIONS 20

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
    // Reads the configuration, then the knowledge base; throws ekb::LoadError (after
    // logging every finding) if the file has an error or cannot be read.
    EnvironmentKnowledgeBase() {
        try {
            load(ekb::KnowledgeBase::configured(configurationPath(), dropInOptions()));
        } catch (const ekb::LoadError &error) {
            report(error);
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

private:
    // The configuration the robot's class reads; nullopt: EKB_CONFIG, else the default.
    static std::optional<std::string> configurationPath() {
#ifdef EKB_DROP_IN_ROS
        std::string package = packagePath(ROS_PACKAGE_NAME);
        if (!package.empty()) return package + "/config/environmentKnowledgeBaseConfiguration.ini";
        ROS_WARN("package %s not found on ROS_PACKAGE_PATH: reading the configuration that EKB_CONFIG names, "
                 "else config/environmentKnowledgeBaseConfiguration.ini under the current folder",
                 ROS_PACKAGE_NAME);
#endif
        return std::nullopt;
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
        return options;
    }

    // Logs every finding of a refused file, or why it could not be read.
    static void report(const ekb::LoadError &error) {
        if (error.findings().empty()) log(ekb::Severity::error, error.what());
        for (const ekb::Finding &finding : error.findings()) {
            std::string line = finding.toString();
            if (finding.help) line += " (help: " + *finding.help + ")";
            log(finding.severity, line);
        }
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
