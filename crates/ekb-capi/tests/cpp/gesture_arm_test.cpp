// The drop-in with EKB_GESTURE_ARM=1: KeyValueType has the `2026-03` robot's gestureArm,
// "left" or "right" as the file says, "" where it says nothing.
//
// Usage: ekb-gesture-arm-test FILE (location 2 gestures with the left arm, location 1 with none)
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "environmentKnowledgeBaseInterface.h"

int main(int argc, char **argv) {
    if (argc != 2) return 2;
    char folder[] = "/tmp/ekb-gesture-arm-XXXXXX";
    std::string config = std::string(mkdtemp(folder)) + "/environmentKnowledgeBaseConfiguration.ini";
    std::ofstream(config) << "knowledgeBase " << argv[1] << "\n";
    setenv("EKB_CONFIG", config.c_str(), 1);
    Environment::EnvironmentKnowledgeBase kb;
    KeyValueType one, two;
    bool found = kb.getValue(1, &one) && kb.getValue(2, &two);
    std::remove(config.c_str());
    std::remove(folder);
    if (!found || std::strcmp(one.gestureArm, "") != 0 || std::strcmp(two.gestureArm, "left") != 0) {
        std::printf("FAIL gestureArm: \"%s\", \"%s\"\n", found ? one.gestureArm : "?", found ? two.gestureArm : "?");
        return 1;
    }
    std::printf("gestureArm: \"\", \"left\"\n");
    return 0;
}
