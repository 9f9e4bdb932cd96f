//! The one module of `routh-jit` with `unsafe` code: ownership of the finished machine code and
//! the call into it.
//!
//! [`Code`] owns the `JITModule` whose memory holds the code of one or more functions, and frees
//! that memory when the last [`Entry`] into it is dropped (each entry holds an `Arc<Code>`). An
//! [`Entry`] checks the lengths of the buffers it is given against the lengths the function was
//! compiled for before every call, so that the code never reads or writes out of bounds.

use cranelift_jit::JITModule;
use cranelift_module::FuncId;
use routh_tape::INPUTS;
use std::fmt;
use std::mem::ManuallyDrop;
use std::sync::Arc;

/// The signature of a compiled tape: `f(inputs, params, out)`.
type RawFn = unsafe extern "C" fn(*const f64, *const f64, *mut f64);

/// A finalized `JITModule`: its code and constants stay mapped until this is dropped.
pub(crate) struct Code {
    module: ManuallyDrop<JITModule>,
}

// SAFETY: after `finalize_definitions` (done before a `Code` is made, see `Code::new`) the
// module is never used again except to free its memory in `Drop`, which has exclusive access
// (`&mut self`, the last `Arc` gone). The code and read-only data it maps are immutable, so
// calling into them from several threads at once is sound (each call works on its own stack
// and on the caller's buffers). The module's interior `RefCell` (its symbol cache) is only
// used while compiling, before the `Code` exists.
unsafe impl Send for Code {}
// SAFETY: see `Send` above: no method of `Code` touches the module through `&self`.
unsafe impl Sync for Code {}

impl Code {
    /// Takes ownership of a module whose definitions are finalized.
    pub(crate) fn new(module: JITModule) -> Arc<Code> {
        Arc::new(Code {
            module: ManuallyDrop::new(module),
        })
    }

    /// The entry point of function `id` of this module, compiled with the signature
    /// `f(inputs: *const f64, params: *const f64, out: *mut f64)`, reading [`INPUTS`] values of
    /// `inputs`, `params` values of `params` and writing `outputs` values of `out`.
    ///
    /// The caller guarantees (it is the compiler of this crate, `crate::compile`) that `id` is
    /// a function of this module, defined with that signature, that reads only
    /// `inputs[0..INPUTS]` and `params[0..params]` and writes only `out[0..outputs]`.
    pub(crate) fn entry(self: &Arc<Code>, id: FuncId, params: usize, outputs: usize) -> Entry {
        let ptr = self.module.get_finalized_function(id);
        // SAFETY: `ptr` is the start of the finalized (executable) code of function `id`, whose
        // signature is `RawFn` under the host's default calling convention, which is the one
        // `extern "C"` denotes (`make_signature` in `crate::compile::compile_all`). A data pointer and a function
        // pointer have the same size on every host Cranelift supports.
        let f = unsafe { std::mem::transmute::<*const u8, RawFn>(ptr) };
        Entry {
            code: Arc::clone(self),
            f,
            params,
            outputs,
        }
    }
}

impl Drop for Code {
    fn drop(&mut self) {
        // SAFETY: the module is taken exactly once, here, and not used afterwards.
        let module = unsafe { ManuallyDrop::take(&mut self.module) };
        // SAFETY: every `Entry` holds an `Arc<Code>`; this runs when the last one is gone, so
        // no function of the module is executing or can be called after its memory is freed.
        unsafe { module.free_memory() };
    }
}

/// A callable compiled function and the module that owns its code.
#[derive(Clone)]
pub(crate) struct Entry {
    /// Keeps the code mapped while the entry lives.
    code: Arc<Code>,
    f: RawFn,
    params: usize,
    outputs: usize,
}

impl fmt::Debug for Entry {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Entry")
            .field("params", &self.params)
            .field("outputs", &self.outputs)
            .field("modules", &Arc::strong_count(&self.code))
            .finish()
    }
}

impl Entry {
    /// Runs the function on `inputs` (`[ω, γ, p_ψ]`) and `params`, writing the first
    /// [`Entry::outputs`] values of `out`, if `params` and `out` are at least as long as the
    /// function reads and writes; returns whether it ran.
    #[inline]
    pub(crate) fn call(&self, inputs: &[f64; INPUTS], params: &[f64], out: &mut [f64]) -> bool {
        if params.len() < self.params || out.len() < self.outputs {
            return false;
        }
        // SAFETY: the code is mapped while `self.code` lives (it does for this call). The
        // function reads `inputs[0..INPUTS]` (an array of that length), `params[0..self.params]`
        // and writes `out[0..self.outputs]` only (the contract of `Code::entry`), and both
        // slices were just checked to be at least that long; `out` is a unique borrow, so
        // nothing else reads it while it is written. The code calls only the `extern "C"`
        // wrappers of `crate::libcalls`, which cannot unwind.
        unsafe { (self.f)(inputs.as_ptr(), params.as_ptr(), out.as_mut_ptr()) };
        true
    }

    /// The number of parameter values read.
    pub(crate) fn params(&self) -> usize {
        self.params
    }

    /// The number of outputs written.
    pub(crate) fn outputs(&self) -> usize {
        self.outputs
    }
}
