//! What the lab can show: the walk's view, the side panel, the curve charts, the pick lists.

/// The walk as seen from the side or from the front.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// Sagittal plane: x forward to the right, y up.
    Side,
    /// Frontal plane: z (right) to the left, as when facing the walker; y up.
    Front,
}

/// The panel shown beside the walk on narrow screens.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Panel {
    /// The parameter editor.
    Editor,
    /// Curve charts.
    Curves,
    /// Joint angle traces.
    Joints,
    /// The optimiser's choices and landscape.
    Optimiser,
}

impl Panel {
    /// Every panel, in tab order.
    pub const ALL: [Panel; 4] = [Panel::Editor, Panel::Curves, Panel::Joints, Panel::Optimiser];

    /// Its tab title.
    #[must_use]
    pub(crate) fn title(self) -> &'static str {
        match self {
            Panel::Editor => "Parameters",
            Panel::Curves => "Curves",
            Panel::Joints => "Joints",
            Panel::Optimiser => "Optimiser",
        }
    }
}

/// What a pick list chooses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PickKind {
    /// A preset, whose parameters replace the current ones (one undoable edit).
    Preset,
    /// `terrain.kind`.
    Terrain,
}

/// A curve chart's choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CurveView {
    /// Pelvic rotation (deg) over the right leg's cycle.
    PelvisRotation,
    /// Pelvic obliquity (deg).
    PelvisObliquity,
    /// Pelvic tilt (deg).
    PelvisTilt,
    /// Pelvis height's shape between keys.
    PelvisVertical,
    /// Lateral pelvis position (cm).
    PelvisLateral,
    /// Forward progress between keys, both halves.
    PelvisForward,
    /// The swinging foot's forward progress.
    SwingForward,
    /// The swinging foot's lateral weight.
    SwingLateral,
    /// Heel height of the swinging foot (cm): the design and the step's adapted curve.
    SwingHeelHeight,
    /// The swinging foot's ankle, against the shank (deg, dorsiflexion +): design and adapted.
    Ankle,
    /// Heel rise (foot–ground angle, deg).
    HeelRise,
    /// Shoulder flexion of the right arm (deg), as played.
    Shoulder,
    /// Elbow flexion of the right arm (deg), as played.
    Elbow,
}

impl CurveView {
    /// Every chart, in `c` order.
    pub const ALL: [CurveView; 13] = [
        CurveView::PelvisRotation,
        CurveView::PelvisObliquity,
        CurveView::PelvisTilt,
        CurveView::PelvisVertical,
        CurveView::PelvisLateral,
        CurveView::PelvisForward,
        CurveView::SwingForward,
        CurveView::SwingLateral,
        CurveView::SwingHeelHeight,
        CurveView::Ankle,
        CurveView::HeelRise,
        CurveView::Shoulder,
        CurveView::Elbow,
    ];

    /// Chart title with its unit.
    #[must_use]
    pub(crate) fn title(self) -> &'static str {
        match self {
            CurveView::PelvisRotation => "pelvic rotation (deg)",
            CurveView::PelvisObliquity => "pelvic obliquity (deg)",
            CurveView::PelvisTilt => "pelvic tilt (deg)",
            CurveView::PelvisVertical => "pelvis vertical ds>ms, ms>ds (0-1)",
            CurveView::PelvisLateral => "pelvis lateral (cm)",
            CurveView::PelvisForward => "pelvis forward ds>ms, ms>ds (0-1)",
            CurveView::SwingForward => "swing foot forward (0-1)",
            CurveView::SwingLateral => "swing foot lateral (0-1)",
            CurveView::SwingHeelHeight => "swing heel height (cm)",
            CurveView::Ankle => "swing ankle, dorsiflexion + (deg)",
            CurveView::HeelRise => "heel rise (deg)",
            CurveView::Shoulder => "shoulder flexion, right (deg)",
            CurveView::Elbow => "elbow flexion, right (deg)",
        }
    }
}
