//! The lab opened in-process as the tests open it (`mod lab_state;`): its recovery of the
//! embedded default kept in a folder of this test process, not the user's state folder, where
//! a recovery the developer's own lab left behind would open its overlay over every test.

use gaitlab::tui::app::App;
use std::path::Path;

/// [`gaitlab::tui::load_app`], the embedded default's recovery under the system's temporary
/// folder (a folder per test process, never written by the lab's tests).
pub fn load_app(config: Option<&Path>, sets: &[String]) -> gaitlab::Result<App> {
    gaitlab::tui::recovery::use_state_folder(
        std::env::temp_dir().join(format!("gaitlab-test-state-{}", std::process::id())),
    );
    gaitlab::tui::load_app(config, sets)
}
