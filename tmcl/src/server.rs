//! The module served to hosts over TCP and a pseudo-terminal, the model advancing with
//! wall-clock time. One command is executed at a time (the module sits behind one lock).

use crate::chip::{ModelChip, Spi429};
use crate::link::Link;
use crate::module::Module;
use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Duration, Instant};

/// The module and the clock that ties model time to wall-clock time.
pub struct Shared {
    pub module: Module<ModelChip>,
    start_wall: Instant,
    start_cycle: u64,
    time_scale: f64,
}

impl Shared {
    /// Link time in milliseconds (wall clock).
    fn wall_ms(&self) -> u64 {
        self.start_wall.elapsed().as_millis() as u64
    }
    /// The chip cycle that corresponds to now.
    fn target_cycle(&self) -> u64 {
        let secs = self.start_wall.elapsed().as_secs_f64() * self.time_scale;
        self.start_cycle + (secs * self.module.chip.fclk() as f64) as u64
    }
}

/// A running server.
pub struct Server {
    shared: Arc<Mutex<Shared>>,
    stop: Arc<AtomicBool>,
    threads: Vec<std::thread::JoinHandle<()>>,
    /// The TCP address actually bound (port 0 picks a free port).
    pub tcp_addr: Option<std::net::SocketAddr>,
    /// Path of the pseudo-terminal's slave side.
    pub pty_path: Option<String>,
}

/// Feeds the bytes a client sent (possibly none) to its link and returns the bytes to send back:
/// replies to complete frames and whatever the link emits on its own (timeouts, events).
fn exchange(sh: &Arc<Mutex<Shared>>, link: &mut Link, bytes: &[u8]) -> Vec<u8> {
    let mut g = lock(sh);
    let now = g.wall_ms();
    let mut out = if bytes.is_empty() { Vec::new() } else { link.feed(&mut g.module, bytes, now) };
    out.extend(link.poll(&mut g.module, now));
    out
}

fn lock(s: &Arc<Mutex<Shared>>) -> MutexGuard<'_, Shared> {
    // A panic in another thread must not take the module down with it.
    s.lock().unwrap_or_else(|e| e.into_inner())
}

/// Server options.
pub struct Options {
    pub tcp: Option<String>,
    pub pty: bool,
    pub time_scale: f64,
    pub frame_timeout_ms: u64,
}

impl Server {
    pub fn start(module: Module<ModelChip>, opt: &Options) -> Result<Server, String> {
        if !(opt.time_scale > 0.0 && opt.time_scale.is_finite()) {
            return Err(format!("--time-scale must be a positive number, got {}", opt.time_scale));
        }
        let start_cycle = module.chip.cycle();
        let shared = Arc::new(Mutex::new(Shared { module, start_wall: Instant::now(), start_cycle, time_scale: opt.time_scale }));
        let stop = Arc::new(AtomicBool::new(false));
        let mut threads = Vec::new();
        let mut tcp_addr = None;
        let mut pty_path = None;
        if let Some(addr) = &opt.tcp {
            let l = TcpListener::bind(addr).map_err(|e| format!("cannot listen on {addr}: {e}"))?;
            tcp_addr = l.local_addr().ok();
            l.set_nonblocking(true).map_err(|e| e.to_string())?;
            let (sh, st, ft) = (shared.clone(), stop.clone(), opt.frame_timeout_ms);
            threads.push(std::thread::spawn(move || accept_loop(l, sh, st, ft)));
        }
        if opt.pty {
            let pty = Pty::open()?;
            pty_path = Some(pty.path.clone());
            let (sh, st, ft) = (shared.clone(), stop.clone(), opt.frame_timeout_ms);
            threads.push(std::thread::spawn(move || pty_loop(pty, sh, st, ft)));
        }
        let (sh, st) = (shared.clone(), stop.clone());
        threads.push(std::thread::spawn(move || clock_loop(sh, st)));
        Ok(Server { shared, stop, threads, tcp_addr, pty_path })
    }

    /// Access to the module (tests set inputs and read state through it).
    pub fn with_module<R>(&self, f: impl FnOnce(&mut Module<ModelChip>) -> R) -> R {
        f(&mut lock(&self.shared).module)
    }

    /// Runs until the process is terminated.
    pub fn wait(self) {
        for t in self.threads {
            let _ = t.join();
        }
    }

    pub fn shutdown(self) {
        self.stop.store(true, Ordering::SeqCst);
        for t in self.threads {
            let _ = t.join();
        }
    }
}

/// Advances the module to follow wall-clock time, one module millisecond per lock.
fn clock_loop(sh: Arc<Mutex<Shared>>, stop: Arc<AtomicBool>) {
    let mut warned = false;
    while !stop.load(Ordering::SeqCst) {
        let behind = {
            let mut g = lock(&sh);
            let target = g.target_cycle();
            let now = g.module.chip.cycle();
            if target > now {
                let cpm = g.module.chip.fclk() / 1000;
                let step_to = target.min(now + cpm.max(1));
                g.module.run_until_cycle(step_to);
                if let Some(e) = g.module.eeprom_error.take() {
                    eprintln!("tmcl serve: EEPROM write failed: {e}");
                }
                target.saturating_sub(step_to)
            } else {
                0
            }
        };
        if behind == 0 {
            std::thread::sleep(Duration::from_millis(1));
        } else if !warned && behind > 32_000_000 {
            warned = true;
            eprintln!("tmcl serve: the model runs slower than the requested time scale; module time lags");
        }
    }
}

fn accept_loop(l: TcpListener, sh: Arc<Mutex<Shared>>, stop: Arc<AtomicBool>, ft: u64) {
    while !stop.load(Ordering::SeqCst) {
        match l.accept() {
            Ok((s, _)) => {
                let (sh, st) = (sh.clone(), stop.clone());
                std::thread::spawn(move || tcp_client(s, sh, st, ft));
            }
            Err(e) if e.kind() == std::io::ErrorKind::WouldBlock => std::thread::sleep(Duration::from_millis(5)),
            Err(_) => std::thread::sleep(Duration::from_millis(20)),
        }
    }
}

fn tcp_client(mut s: TcpStream, sh: Arc<Mutex<Shared>>, stop: Arc<AtomicBool>, ft: u64) {
    let _ = s.set_nodelay(true);
    let _ = s.set_read_timeout(Some(Duration::from_millis(5)));
    // A client that does not read its replies is dropped, it cannot stall the module.
    let _ = s.set_write_timeout(Some(Duration::from_secs(5)));
    let mut link = {
        let g = lock(&sh);
        Link::for_module(&g.module)
    };
    link.frame_timeout_ms = ft;
    let mut buf = [0u8; 4096];
    while !stop.load(Ordering::SeqCst) {
        let n = match s.read(&mut buf) {
            Ok(0) => return,
            Ok(n) => n,
            Err(e) if matches!(e.kind(), std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut) => 0,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => 0,
            Err(_) => return,
        };
        let out = exchange(&sh, &mut link, &buf[..n]);
        if !out.is_empty() && s.write_all(&out).is_err() {
            return;
        }
    }
}

/// The master side of a pseudo-terminal; the slave stays open so the master never sees EIO.
struct Pty {
    master: std::fs::File,
    _slave: std::fs::File,
    path: String,
}

impl Pty {
    fn open() -> Result<Pty, String> {
        use std::os::unix::io::FromRawFd;
        // SAFETY: plain libc calls on descriptors this function owns; every result is checked.
        unsafe {
            let fd = libc::posix_openpt(libc::O_RDWR | libc::O_NOCTTY);
            if fd < 0 {
                return Err(format!("posix_openpt failed: {}", std::io::Error::last_os_error()));
            }
            let master = std::fs::File::from_raw_fd(fd);
            if libc::grantpt(fd) != 0 || libc::unlockpt(fd) != 0 {
                return Err(format!("cannot unlock the pseudo-terminal: {}", std::io::Error::last_os_error()));
            }
            let mut name = [0 as libc::c_char; 256];
            if libc::ptsname_r(fd, name.as_mut_ptr(), name.len()) != 0 {
                return Err(format!("ptsname failed: {}", std::io::Error::last_os_error()));
            }
            let path = std::ffi::CStr::from_ptr(name.as_ptr()).to_string_lossy().into_owned();
            let slave = std::fs::OpenOptions::new().read(true).write(true).open(&path).map_err(|e| format!("cannot open {path}: {e}"))?;
            // Raw mode: bytes pass unchanged, no echo by the line discipline.
            use std::os::unix::io::AsRawFd;
            let sfd = slave.as_raw_fd();
            let mut t: libc::termios = std::mem::zeroed();
            if libc::tcgetattr(sfd, &mut t) == 0 {
                libc::cfmakeraw(&mut t);
                libc::tcsetattr(sfd, libc::TCSANOW, &t);
            }
            let fl = libc::fcntl(fd, libc::F_GETFL);
            libc::fcntl(fd, libc::F_SETFL, fl | libc::O_NONBLOCK);
            Ok(Pty { master, _slave: slave, path })
        }
    }
}

fn pty_loop(mut pty: Pty, sh: Arc<Mutex<Shared>>, stop: Arc<AtomicBool>, ft: u64) {
    let mut link = {
        let g = lock(&sh);
        Link::for_module(&g.module)
    };
    link.frame_timeout_ms = ft;
    let mut buf = [0u8; 4096];
    let mut pending: Vec<u8> = Vec::new();
    while !stop.load(Ordering::SeqCst) {
        let n = match pty.master.read(&mut buf) {
            Ok(n) => n,
            Err(_) => 0,
        };
        let out = exchange(&sh, &mut link, &buf[..n]);
        pending.extend(out);
        if !pending.is_empty() {
            match pty.master.write(&pending) {
                Ok(k) => {
                    pending.drain(..k);
                }
                Err(_) => {
                    // Nobody reads the terminal: keep at most 64 KiB, drop the oldest.
                    if pending.len() > 65536 {
                        let cut = pending.len() - 65536;
                        pending.drain(..cut);
                    }
                }
            }
        }
        if n == 0 {
            std::thread::sleep(Duration::from_millis(1));
        }
    }
}
