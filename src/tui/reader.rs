//! The reader thread: terminal input becomes the event loop's [`Input`]s, and the two things that
//! must not wait in line are decided here, as each key arrives, not when the loop gets to it.
//!
//! - **A paste that came as keys is a paste.** A terminal or multiplexer that does not bracket a
//!   paste (`tmux paste-buffer` without `-p`, `tmux send-keys` of a long string, some web
//!   terminals) delivers it as a storm of key presses: 100 kB of text applied 100 000 commands,
//!   for 93 s, during which `q` waited its turn. The reader holds each printable key for up to
//!   [`GAP`] to see whether more follow; a burst of at least [`PASTE_KEYS`] text keys (printable
//!   characters, Enter, Tab), no two of them further apart than [`GAP`] (once it is a paste,
//!   [`PASTE_QUIET`]), is handed over as one `Event::Paste` of its text, which the app treats
//!   like a bracketed paste: typed into the field being edited (refused whole when too long),
//!   ignored with a note on the main screen. A burst of one key repeated is a held key (key
//!   repeat bunched by a slow link, or a program driving the terminal), not text: its keys go on
//!   as keys, and a different key after [`HELD_RUN`] of them starts a burst of its own. A person
//!   typing is never held up beyond [`GAP`], and a short burst (type-ahead over a slow link)
//!   goes on as the keys it was.
//! - **Quitting jumps the queue.** Ctrl-C sets a flag the loop looks at between any two events
//!   (like a signal) and arms the [`Watchdog`], so that it quits at once however many events
//!   wait. A `q` or Esc typed while at least [`DEEP`] key presses wait to be applied is sent as
//!   [`Input::Urgent`] and flagged: the loop drops the keys waiting before it (the status line
//!   says how many) and applies it next.
//!
//! [`Watchdog`]: super::watchdog::Watchdog

use std::io;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::Sender;
use std::time::Duration;

use ratatui::crossterm::event::{self, Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers};

use super::watchdog::Watchdog;
use super::workers::Report;

/// The longest pause between two keys of one burst. Typing, even at 200 words a minute, leaves
/// 50 ms or more between keys; a paste arrives as fast as the terminal writes it (a few
/// microseconds a key, in pieces a millisecond apart under tmux).
pub const GAP: Duration = Duration::from_millis(10);

/// Once a burst is a paste, the quiet that ends it: a terminal that stalls while it writes a long
/// paste (a busy machine) would otherwise cut it into pieces, of which a short last one would act
/// as keys, and swallow a `q` typed after it into the next piece.
pub const PASTE_QUIET: Duration = Duration::from_millis(100);

/// The fewest text keys in one burst that make it a paste. Type-ahead over a slow link (keys
/// typed during a stall, delivered in one packet) stays well below it.
pub const PASTE_KEYS: usize = 64;

/// The most bytes of text one paste made of keys holds; the rest of a longer one follows as
/// further pastes. An input takes far fewer ([`crate::tui::text_input::MAX_CHARS`]) and refuses a
/// longer paste whole.
pub const PASTE_CAP: usize = 1 << 20;

/// Key presses waiting to be applied behind which a `q` or Esc jumps the queue.
pub const DEEP: usize = 32;

/// What the loop waits for: the terminal's events and the workers' reports, on one channel so
/// that one wait covers both.
pub enum Input {
    /// A terminal event (or the read error that ends the program).
    Terminal(io::Result<Event>),
    /// A `q` or Esc typed behind [`DEEP`] waiting keys: the loop drops those and applies it.
    Urgent(Event),
    /// A worker's report (boxed: a report of loaded FE points is several times the size of a
    /// key event, and every event on the channel would pay for it).
    Work(Box<Report>),
}

impl From<Report> for Input {
    fn from(report: Report) -> Input {
        Input::Work(Box::new(report))
    }
}

/// What the reader tells the loop out of band: how many key presses it has sent and the loop
/// has not taken yet, whether an urgent key waits, whether Ctrl-C was pressed.
#[derive(Debug, Default)]
pub struct Keyboard {
    queued: AtomicUsize,
    urgent: AtomicUsize,
    interrupt: AtomicBool,
}

impl Keyboard {
    /// The loop has taken `input` from the channel.
    pub fn taken(&self, input: &Input) {
        match input {
            Input::Terminal(Ok(event)) if is_press(event) => {
                let _ = self
                    .queued
                    .fetch_update(Ordering::SeqCst, Ordering::SeqCst, |n| n.checked_sub(1));
            }
            Input::Urgent(_) => {
                for count in [&self.queued, &self.urgent] {
                    let _ = count
                        .fetch_update(Ordering::SeqCst, Ordering::SeqCst, |n| n.checked_sub(1));
                }
            }
            _ => {}
        }
    }

    /// True when an urgent key waits in the channel (see [`Input::Urgent`]), or is about to.
    pub fn urgent(&self) -> bool {
        self.urgent.load(Ordering::SeqCst) > 0
    }

    /// True once Ctrl-C has been pressed.
    pub fn interrupted(&self) -> bool {
        self.interrupt.load(Ordering::SeqCst)
    }

    /// Key presses sent and not yet taken.
    pub fn queued(&self) -> usize {
        self.queued.load(Ordering::SeqCst)
    }
}

/// True for a key press (not a release or repeat report, which this program does not ask for).
fn is_press(event: &Event) -> bool {
    matches!(event, Event::Key(key) if key.kind == KeyEventKind::Press)
}

/// The character a key press types into pasted text: printable characters (shifted or not),
/// Enter as a line break, Tab; None for every other key (arrows, Ctrl- and Alt- keys, Esc).
pub fn text_of(key: &KeyEvent) -> Option<char> {
    if key.kind != KeyEventKind::Press || !(key.modifiers - KeyModifiers::SHIFT).is_empty() {
        return None;
    }
    match key.code {
        KeyCode::Char(c) if !c.is_control() => Some(c),
        KeyCode::Enter => Some('\n'),
        KeyCode::Tab => Some('\t'),
        _ => None,
    }
}

/// Ctrl-C: quit from anywhere, without asking.
fn is_interrupt(key: &KeyEvent) -> bool {
    key.kind == KeyEventKind::Press
        && key.modifiers.contains(KeyModifiers::CONTROL)
        && matches!(key.code, KeyCode::Char('c' | 'C'))
}

/// `q` or Esc, which jump a deep queue.
fn is_quit_key(key: &KeyEvent) -> bool {
    key.kind == KeyEventKind::Press
        && key.modifiers.is_empty()
        && matches!(key.code, KeyCode::Char('q') | KeyCode::Esc)
}

/// The shortest run of one key that is a key held down: another key after it starts a new burst
/// rather than making the run text (`q` right after a held `j`, bunched by a slow link, quits).
const HELD_RUN: usize = 8;

/// The most keys of one held key in one burst: a burst of them goes on at this size, so that a
/// program that drives the terminal with one key and no pause is not held up.
const HELD_KEYS: usize = 256;

/// The text keys of one burst, as they came.
#[derive(Debug, Default)]
pub struct Burst {
    /// The keys, while the burst may still be keys: shorter than [`PASTE_KEYS`], or one key.
    keys: Vec<KeyEvent>,
    /// Their text, up to [`PASTE_CAP`] bytes.
    text: String,
    count: usize,
    one_key: bool,
}

impl Burst {
    /// Adds a text key (`c` is its [`text_of`]).
    pub fn push(&mut self, key: KeyEvent, c: char) {
        self.one_key = self.count == 0 || (self.one_key && self.keys.first() == Some(&key));
        self.count += 1;
        if self.text.len() < PASTE_CAP {
            self.text.push(c);
        }
        if self.is_paste() {
            self.keys = Vec::new();
        } else {
            self.keys.push(key);
        }
    }

    /// True when `key` does not belong to this burst but starts the next one: the burst so far is
    /// one key held down ([`HELD_RUN`] or more of it), and `key` is another.
    pub fn ends_before(&self, key: &KeyEvent) -> bool {
        self.one_key && self.count >= HELD_RUN && self.keys.first() != Some(key)
    }

    /// True when the burst is text, not keys: [`PASTE_KEYS`] or more, not all one key.
    pub fn is_paste(&self) -> bool {
        self.count >= PASTE_KEYS && !self.one_key
    }

    /// True when the burst should go on now rather than wait for its end: a held key's
    /// [`HELD_KEYS`], or a paste's [`PASTE_CAP`].
    pub fn full(&self) -> bool {
        (self.one_key && self.count >= HELD_KEYS) || self.text.len() >= PASTE_CAP
    }

    /// The burst as the loop gets it: one paste of its text, or its keys as they came (fewer
    /// than [`PASTE_KEYS`], or one key held down).
    pub fn finish(self) -> Vec<Event> {
        if self.is_paste() {
            vec![Event::Paste(self.text)]
        } else {
            self.keys.into_iter().map(Event::Key).collect()
        }
    }
}

/// Reads terminal events on a thread of its own and hands them over the loop's channel, so that
/// the loop never blocks inside the terminal library and always gets back to its signals. The
/// thread ends at the first read error (the terminal is gone) or when the loop has gone.
pub fn spawn(sender: Sender<Input>, keyboard: Arc<Keyboard>, watchdog: Watchdog) {
    std::thread::spawn(move || {
        let reader = Reader {
            sender,
            keyboard,
            watchdog,
        };
        let _ = reader.run();
    });
}

/// The reader thread's state.
struct Reader {
    sender: Sender<Input>,
    keyboard: Arc<Keyboard>,
    watchdog: Watchdog,
}

/// The loop has gone, or the terminal has: the reader ends.
struct Ended;

impl Reader {
    fn run(&self) -> Result<(), Ended> {
        let mut held: Option<Event> = None;
        loop {
            let event = match held.take() {
                Some(event) => event,
                None => self.read()?,
            };
            let Event::Key(key) = &event else {
                self.send(event)?;
                continue;
            };
            let Some(c) = text_of(key) else {
                self.send(event)?;
                continue;
            };
            // A text key: gather those that follow within GAP of each other.
            let mut burst = Burst::default();
            burst.push(*key, c);
            while !burst.full() {
                let gap = if burst.is_paste() { PASTE_QUIET } else { GAP };
                if !event::poll(gap).map_err(|e| self.failed(e))? {
                    break;
                }
                let next = self.read()?;
                match &next {
                    Event::Key(key) if let Some(c) = text_of(key) => {
                        if burst.ends_before(key) {
                            for event in std::mem::take(&mut burst).finish() {
                                self.send(event)?;
                            }
                        }
                        burst.push(*key, c);
                    }
                    _ => {
                        // Not text: the burst ends before it, and it is looked at on its own.
                        held = Some(next);
                        break;
                    }
                }
            }
            for event in burst.finish() {
                self.send(event)?;
            }
        }
    }

    /// The next terminal event; a read error is sent on (the loop ends) and ends the reader.
    fn read(&self) -> Result<Event, Ended> {
        let event = event::read().map_err(|e| self.failed(e))?;
        if let Event::Key(key) = &event
            && is_interrupt(key)
        {
            self.keyboard.interrupt.store(true, Ordering::SeqCst);
            self.watchdog.arm_quit();
        }
        Ok(event)
    }

    /// Sends the read error that ends the loop.
    fn failed(&self, error: io::Error) -> Ended {
        let _ = self.sender.send(Input::Terminal(Err(error)));
        Ended
    }

    /// Sends one event, as urgent where it is a `q` or Esc behind a deep queue.
    fn send(&self, event: Event) -> Result<(), Ended> {
        let urgent =
            matches!(&event, Event::Key(key) if is_quit_key(key)) && self.keyboard.queued() >= DEEP;
        if is_press(&event) {
            self.keyboard.queued.fetch_add(1, Ordering::SeqCst);
        }
        // Counted before the send, so that the loop, which counts it down when it takes the key,
        // never sees a count for a key it has already taken (it would then drop the keys that
        // follow). Seen a moment before the key is in the channel, it drops only keys that the
        // key would have dropped anyway.
        let input = if urgent {
            self.keyboard.urgent.fetch_add(1, Ordering::SeqCst);
            Input::Urgent(event)
        } else {
            Input::Terminal(Ok(event))
        };
        self.sender.send(input).map_err(|_| Ended)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(c: char) -> KeyEvent {
        KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE)
    }

    /// What the reader sends for `text` typed in one burst (split where a held key ends).
    fn burst(text: &str) -> Vec<Event> {
        let mut burst = Burst::default();
        let mut sent = Vec::new();
        for c in text.chars() {
            let key = match c {
                '\n' => KeyEvent::new(KeyCode::Enter, KeyModifiers::NONE),
                c if c.is_ascii_uppercase() => KeyEvent::new(KeyCode::Char(c), KeyModifiers::SHIFT),
                c => key(c),
            };
            if burst.ends_before(&key) {
                sent.extend(std::mem::take(&mut burst).finish());
            }
            burst.push(key, text_of(&key).unwrap());
        }
        sent.extend(burst.finish());
        sent
    }

    /// Issue 46 (9): 100 kB of text that came as keys is one paste of that text, not 100 000
    /// commands; line breaks and capitals (shifted keys) are text too.
    #[test]
    fn a_long_burst_of_text_keys_is_one_paste_of_its_text() {
        let text: String = "jLq:x\ny=1 ".chars().cycle().take(100_000).collect();
        assert_eq!(burst(&text), vec![Event::Paste(text.clone())]);
        let just = &text[..PASTE_KEYS];
        assert_eq!(burst(just), vec![Event::Paste(just.to_string())]);
    }

    /// Type-ahead (fewer than PASTE_KEYS keys at once) goes on as the keys it was, in order.
    #[test]
    fn a_short_burst_stays_keys() {
        let text = "jjjjjjjjLLq".repeat(5);
        assert!(text.len() < PASTE_KEYS);
        let events = burst(&text);
        assert_eq!(events.len(), text.len());
        assert_eq!(events[0], Event::Key(key('j')));
        assert_eq!(
            events[8],
            Event::Key(KeyEvent::new(KeyCode::Char('L'), KeyModifiers::SHIFT))
        );
    }

    /// A held key (one key repeated, however many) is not text: each `l` steps the value, as it
    /// did; the reader hands them on every HELD_KEYS.
    #[test]
    fn one_key_repeated_stays_keys_however_many() {
        let events = burst(&"l".repeat(HELD_KEYS));
        assert_eq!(events.len(), HELD_KEYS);
        assert!(events.iter().all(|e| *e == Event::Key(key('l'))));
        // Another key right after them is a key of its own, not the end of a text: `q` quits.
        let mut events = burst(&format!("{}q", "j".repeat(300)));
        assert_eq!(events.pop(), Some(Event::Key(key('q'))));
        assert_eq!(events.len(), 300);
        // A short run is text like any other (indentation in a pasted block).
        let text = format!("{}{}", " ".repeat(HELD_RUN - 1), "x=1;y".repeat(20));
        assert_eq!(burst(&text), vec![Event::Paste(text.clone())]);
    }

    /// A paste beyond the cap keeps its first PASTE_CAP bytes (the app refuses it whole
    /// anyway).
    #[test]
    fn a_huge_paste_is_capped() {
        let text: String = "ab".repeat(PASTE_CAP);
        let events = burst(&text);
        let [Event::Paste(kept)] = events.as_slice() else {
            panic!("{} events", events.len())
        };
        assert_eq!(kept.len(), PASTE_CAP);
        assert!(text.starts_with(kept.as_str()));
    }

    /// What counts as text, as an interrupt, as a quit key.
    #[test]
    fn keys_are_classified() {
        let ctrl = |c| KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL);
        assert_eq!(text_of(&key('q')), Some('q'));
        assert_eq!(
            text_of(&KeyEvent::new(KeyCode::Tab, KeyModifiers::NONE)),
            Some('\t')
        );
        assert_eq!(text_of(&ctrl('c')), None);
        assert_eq!(
            text_of(&KeyEvent::new(KeyCode::Left, KeyModifiers::NONE)),
            None
        );
        assert_eq!(
            text_of(&KeyEvent::new(KeyCode::Char('x'), KeyModifiers::ALT)),
            None
        );
        assert!(is_interrupt(&ctrl('c')));
        assert!(!is_interrupt(&key('c')));
        assert!(is_quit_key(&key('q')));
        assert!(is_quit_key(&KeyEvent::new(
            KeyCode::Esc,
            KeyModifiers::NONE
        )));
        assert!(!is_quit_key(&ctrl('q')));
    }

    /// The loop's count of waiting keys follows what it takes; an urgent key clears the flag.
    #[test]
    fn the_keyboard_counts_what_waits() {
        let keyboard = Keyboard::default();
        keyboard.queued.store(3, Ordering::SeqCst);
        keyboard.urgent.store(1, Ordering::SeqCst);
        keyboard.taken(&Input::Terminal(Ok(Event::Key(key('j')))));
        keyboard.taken(&Input::Terminal(Ok(Event::Paste("x".into()))));
        assert_eq!(keyboard.queued(), 2);
        assert!(keyboard.urgent());
        keyboard.taken(&Input::Urgent(Event::Key(key('q'))));
        assert_eq!(keyboard.queued(), 1);
        assert!(!keyboard.urgent());
    }
}
