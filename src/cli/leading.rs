//! Options written before the command (`gaitlab --set walk.speed_mps=0.8 simulate CONFIG`).
//!
//! The top level's options are the lab's (it runs without a command), and clap accepts them
//! before any command; they used to be dropped without a word when a command followed, so a
//! `--set` there walked the config's own speed and printed its curves as if asked. Now a
//! leading `--set` goes to the command, before its own (a key set twice takes the later
//! value, the command's), and the lab's other options and config, which another command has no
//! use for, are refused with the place to write them.

use crate::cli::args::{Cli, Command, LabArgs};
use crate::error::{Error, Result};

/// Moves `cli`'s leading options into its command, or says why they cannot go there.
///
/// # Errors
/// [`Error::Usage`] for a leading config or lab-only option before a command other than `tui`,
/// a config both before and after `tui`, or a leading `--set` before a command that takes no
/// keys (`presets`, `init`).
pub(crate) fn hoist(cli: &mut Cli) -> Result<()> {
    let Some(command) = cli.command.as_mut() else { return Ok(()) };
    let leading = std::mem::take(&mut cli.lab);
    if let Command::Tui { config, lab } = command {
        match (cli.config.take(), config.as_ref()) {
            (Some(before), Some(own)) => {
                return Err(Error::Usage(format!(
                    "two configs for the lab, `{}` before `tui` and `{}` after it: give one",
                    before.display(),
                    own.display()
                )));
            }
            (before, None) => *config = before,
            (None, Some(_)) => {}
        }
        lab.merge_leading(leading);
        return Ok(());
    }
    let name = command.name();
    if let Some(path) = cli.config.take() {
        return Err(Error::Usage(format!(
            "`{}` before the command is the lab's config, not read by `{name}`: write it after the command (gaitlab {name} --help)",
            path.display()
        )));
    }
    if let Some(option) = leading.lab_only_option() {
        return Err(Error::Usage(format!(
            "{option} before the command is the lab's option, not read by `{name}`: write the command's own options after it (gaitlab {name} --help)"
        )));
    }
    if leading.sets.is_empty() {
        return Ok(());
    }
    let Some(sets) = command.sets_mut() else {
        return Err(Error::Usage(format!("`{name}` takes no --set (it reads no config)")));
    };
    let own = std::mem::take(sets);
    *sets = leading.sets;
    sets.extend(own);
    Ok(())
}

impl LabArgs {
    /// The first lab-only option (not `--set`) written.
    fn lab_only_option(&self) -> Option<&'static str> {
        if self.fps.is_some() {
            Some("--fps")
        } else if self.marker.is_some() {
            Some("--marker")
        } else if self.no_mouse {
            Some("--no-mouse")
        } else {
            None
        }
    }

    /// Takes the options written before `tui` where none is written after it.
    fn merge_leading(&mut self, leading: LabArgs) {
        self.fps = self.fps.or(leading.fps);
        self.marker = self.marker.take().or(leading.marker);
        self.no_mouse |= leading.no_mouse;
        let own = std::mem::take(&mut self.sets);
        self.sets = leading.sets;
        self.sets.extend(own);
    }
}

impl Command {
    /// The command's name as typed.
    fn name(&self) -> &'static str {
        match self {
            Command::Tui { .. } => "tui",
            Command::Check { .. } => "check",
            Command::Simulate { .. } => "simulate",
            Command::Optimise { .. } => "optimise",
            Command::Report { .. } => "report",
            Command::Ik { .. } => "ik",
            Command::Snapshot { .. } => "snapshot",
            Command::Fit { .. } => "fit",
            Command::Compare { .. } => "compare",
            Command::Figures { .. } => "figures",
            Command::Presets => "presets",
            Command::Init { .. } => "init",
        }
    }

    /// The command's `--set` list, if it reads a config.
    fn sets_mut(&mut self) -> Option<&mut Vec<String>> {
        match self {
            Command::Tui { lab, .. } => Some(&mut lab.sets),
            Command::Check { sets, .. }
            | Command::Simulate { sets, .. }
            | Command::Optimise { sets, .. }
            | Command::Report { sets, .. }
            | Command::Ik { sets, .. }
            | Command::Snapshot { sets, .. }
            | Command::Fit { sets, .. }
            | Command::Compare { sets, .. }
            | Command::Figures { sets, .. } => Some(sets),
            Command::Presets | Command::Init { .. } => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    fn hoisted(args: &[&str]) -> Cli {
        let mut cli = Cli::try_parse_from(args).expect("parses");
        hoist(&mut cli).expect("hoists");
        cli
    }

    #[test]
    fn the_lab_takes_leading_options_where_none_follow_the_command() {
        let cli =
            hoisted(&["gaitlab", "--fps", "12", "--set", "walk.sway=0", "a.toml", "tui", "--set", "walk.speed_mps=1"]);
        let Some(Command::Tui { config, lab }) = cli.command else { panic!("not the lab") };
        assert_eq!(config.as_deref(), Some(std::path::Path::new("a.toml")));
        assert_eq!(lab.sets, ["walk.sway=0", "walk.speed_mps=1"]);
        assert_eq!(lab.fps, Some(12.0));
        // Written on both sides, the command's own wins, even when it is the default's value.
        let cli =
            hoisted(&["gaitlab", "--fps", "12", "--marker", "block", "tui", "--fps", "30", "--marker", "braille"]);
        let Some(Command::Tui { lab, .. }) = cli.command else { panic!("not the lab") };
        assert_eq!(lab.fps, Some(30.0));
        assert_eq!(lab.marker.as_deref(), Some("braille"));
        // Two configs: refused.
        let mut cli = Cli::try_parse_from(["gaitlab", "a.toml", "tui", "b.toml"]).expect("parses");
        assert!(hoist(&mut cli).is_err());
    }
}
