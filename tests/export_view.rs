//! The borrowed view that `ekb export` writes is the owned export, byte for byte as `ekb`
//! writes JSON, and value for value otherwise (its locations are written in parts, each as
//! pretty JSON: see `safe_json::InParts`).

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
        let owned = ExportedKnowledgeBase::from(&checked.kb);
        let view = ExportView::new(&checked.kb);
        assert_eq!(written(&view), written(&owned));
        assert_eq!(
            serde_json::to_value(&view).unwrap(),
            serde_json::to_value(&owned).unwrap()
        );
    }
}

/// `value` as `ekb` writes JSON.
fn written(value: &impl serde::Serialize) -> String {
    let mut out = Vec::new();
    ekb::render::safe_json::write(value, &mut out).unwrap();
    String::from_utf8(out).unwrap()
}
