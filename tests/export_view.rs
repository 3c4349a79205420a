//! The borrowed view that `ekb export` writes is the owned export, byte for byte.

use ekb::model::build::Options;
use ekb::model::export::{ExportView, ExportedKnowledgeBase};
use ekb::SourceFile;

#[test]
fn the_view_serializes_as_the_export() {
    let seed = include_str!("../data/environmentKnowledgeBaseInput.dat");
    let current = "robotLocationDescription 3 Hall\nrobotLocationPose 3 1 2 3\n\
                   gestureTarget 3 1 1 1\ngestureArm 3 left\n\
                   culturalKnowledge 3 greeting bow\npreGestureMessageEnglish 3 Hi\n";
    for text in [seed, current] {
        let source = SourceFile::from_bytes("kb.dat", text.as_bytes().to_vec());
        let checked = ekb::check(&source, &Options::default());
        let owned = serde_json::to_string(&ExportedKnowledgeBase::from(&checked.kb)).unwrap();
        let view = serde_json::to_string(&ExportView::new(&checked.kb)).unwrap();
        assert_eq!(view, owned);
    }
}
