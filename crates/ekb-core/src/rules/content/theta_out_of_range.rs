use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::Location;
use crate::rules::{declare_rule, excerpt, LocationContext};
use crate::syntax::{self, Span};

declare_rule! {
    /// ## What it does
    /// Flags a pose whose heading `theta` lies outside -360..=360 degrees.
    ///
    /// ## Why it matters
    /// Headings are degrees. A value like `1570` is usually radians typed by mistake
    /// (`1.570`) or a slipped digit; the robot would turn to an unexpected heading.
    ///
    /// ## Example
    /// ```text
    /// robotLocationPose             2 3.5 6.3 1800
    /// ```
    pub static THETA_OUT_OF_RANGE = {
        name: "theta-out-of-range",
        category: Content,
        severity: Warning,
        fixable: false,
        summary: "theta outside -360..=360",
    };
}

pub fn check(location: &Location<'_>, context: &LocationContext<'_>, out: &mut Diagnostics) {
    let Some(pose) = location.pose else {
        return;
    };
    let theta = pose.value.theta;
    if (-360.0..=360.0).contains(&theta) {
        return;
    }
    let (span, written) = syntax::tokens(pose.span.text(context.source), pose.span.start as usize)
        .nth(2)
        .map_or((pose.span, ""), |(span, token): (Span, _)| (span, token));
    out.push_with(&THETA_OUT_OF_RANGE, || {
        Diagnostic::new(
            &THETA_OUT_OF_RANGE,
            span,
            format!(
                "heading {}° at location {} is outside -360..360: the robot would turn to {}°",
                excerpt(written),
                location.id,
                // Two decimals at most: 360.5 turns to 0.5, 1800 to 0.
                (theta.rem_euclid(360.0) * 100.0).round() / 100.0
            ),
        )
        .at_location(Some(location.id))
        .with_help("write the heading in degrees between -360 and 360")
    });
}
