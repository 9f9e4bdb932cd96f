/// Heavy rigid body about a fixed point carrying a rotor, with a linear gyroscopic term.
#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5*omega.dot(inertia*omega),
    linear = (rotor+coupling*gamma).dot(omega),
    potential = mass*g*com.dot(gamma),
)]
pub struct Gyrostat {
    /// The inertia tensor (symmetric: only its upper triangle is read).
    #[lagrangian(symmetric)]
    pub inertia: Matrix3<f64>,
    pub rotor: Vector3<f64>,
    pub coupling: Matrix3<f64>,
    pub com: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
}
#[doc(hidden)]
#[allow(
    non_upper_case_globals,
    unused_qualifications,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
const _: () = {
    #[automatically_derived]
    impl ::routh::__private::Lagrangian for Gyrostat {
        #[inline]
        fn lagrangian(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __v25: ::routh::__private::f64 = self.com[0usize];
            let __v26: ::routh::__private::f64 = self.com[1usize];
            let __v27: ::routh::__private::f64 = self.com[2usize];
            let __v28: ::routh::__private::f64 = self.mass;
            let __v29: ::routh::__private::f64 = self.g;
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v0 * __t36;
            let __t48: ::routh::__private::f64 = __v1 * __t41;
            let __t49: ::routh::__private::f64 = __v2 * __t46;
            let __t50: ::routh::__private::f64 = __t47 + __t48;
            let __t51: ::routh::__private::f64 = __t49 + __t50;
            let __t52: ::routh::__private::f64 = 0.5f64 * __t51;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t71: ::routh::__private::f64 = __v0 * __t68;
            let __t72: ::routh::__private::f64 = __v1 * __t69;
            let __t73: ::routh::__private::f64 = __v2 * __t70;
            let __t74: ::routh::__private::f64 = __t71 + __t72;
            let __t75: ::routh::__private::f64 = __t73 + __t74;
            let __t76: ::routh::__private::f64 = __v28 * __v29;
            let __t77: ::routh::__private::f64 = __v3 * __v25;
            let __t78: ::routh::__private::f64 = __v4 * __v26;
            let __t79: ::routh::__private::f64 = __v5 * __v27;
            let __t80: ::routh::__private::f64 = __t77 + __t78;
            let __t81: ::routh::__private::f64 = __t79 + __t80;
            let __t82: ::routh::__private::f64 = __t76 * __t81;
            let __t84: ::routh::__private::f64 = __t75 - __t82;
            let __t85: ::routh::__private::f64 = __t52 + __t84;
            __t85
        }
        #[inline]
        fn dl_domega(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            ::routh::__private::Vector3::new(__t91, __t95, __t99)
        }
        #[inline]
        fn dl_dgamma(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __v25: ::routh::__private::f64 = self.com[0usize];
            let __v26: ::routh::__private::f64 = self.com[1usize];
            let __v27: ::routh::__private::f64 = self.com[2usize];
            let __v28: ::routh::__private::f64 = self.mass;
            let __v29: ::routh::__private::f64 = self.g;
            let __t76: ::routh::__private::f64 = __v28 * __v29;
            let __t100: ::routh::__private::f64 = __v25 * __t76;
            let __t102: ::routh::__private::f64 = __v1 * __v19;
            let __t103: ::routh::__private::f64 = __v0 * __v16;
            let __t104: ::routh::__private::f64 = __t102 + __t103;
            let __t105: ::routh::__private::f64 = __v2 * __v22;
            let __t106: ::routh::__private::f64 = __t104 + __t105;
            let __t107: ::routh::__private::f64 = __t106 - __t100;
            let __t108: ::routh::__private::f64 = __v26 * __t76;
            let __t110: ::routh::__private::f64 = __v1 * __v20;
            let __t111: ::routh::__private::f64 = __v0 * __v17;
            let __t112: ::routh::__private::f64 = __t110 + __t111;
            let __t113: ::routh::__private::f64 = __v2 * __v23;
            let __t114: ::routh::__private::f64 = __t112 + __t113;
            let __t115: ::routh::__private::f64 = __t114 - __t108;
            let __t116: ::routh::__private::f64 = __v27 * __t76;
            let __t118: ::routh::__private::f64 = __v1 * __v21;
            let __t119: ::routh::__private::f64 = __v0 * __v18;
            let __t120: ::routh::__private::f64 = __t118 + __t119;
            let __t121: ::routh::__private::f64 = __v2 * __v24;
            let __t122: ::routh::__private::f64 = __t120 + __t121;
            let __t123: ::routh::__private::f64 = __t122 - __t116;
            ::routh::__private::Vector3::new(__t107, __t115, __t123)
        }
        #[inline]
        fn d2l_domega2(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            ::routh::__private::Matrix3::new(
                __v7,
                __v8,
                __v9,
                __v8,
                __v10,
                __v11,
                __v9,
                __v11,
                __v12,
            )
        }
        #[inline]
        fn d2l_domega_dgamma(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            ::routh::__private::Matrix3::new(
                __v16,
                __v17,
                __v18,
                __v19,
                __v20,
                __v21,
                __v22,
                __v23,
                __v24,
            )
        }
        #[inline]
        fn energy(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __v25: ::routh::__private::f64 = self.com[0usize];
            let __v26: ::routh::__private::f64 = self.com[1usize];
            let __v27: ::routh::__private::f64 = self.com[2usize];
            let __v28: ::routh::__private::f64 = self.mass;
            let __v29: ::routh::__private::f64 = self.g;
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v0 * __t36;
            let __t48: ::routh::__private::f64 = __v1 * __t41;
            let __t49: ::routh::__private::f64 = __v2 * __t46;
            let __t50: ::routh::__private::f64 = __t47 + __t48;
            let __t51: ::routh::__private::f64 = __t49 + __t50;
            let __t52: ::routh::__private::f64 = 0.5f64 * __t51;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t71: ::routh::__private::f64 = __v0 * __t68;
            let __t72: ::routh::__private::f64 = __v1 * __t69;
            let __t73: ::routh::__private::f64 = __v2 * __t70;
            let __t74: ::routh::__private::f64 = __t71 + __t72;
            let __t75: ::routh::__private::f64 = __t73 + __t74;
            let __t76: ::routh::__private::f64 = __v28 * __v29;
            let __t77: ::routh::__private::f64 = __v3 * __v25;
            let __t78: ::routh::__private::f64 = __v4 * __v26;
            let __t79: ::routh::__private::f64 = __v5 * __v27;
            let __t80: ::routh::__private::f64 = __t77 + __t78;
            let __t81: ::routh::__private::f64 = __t79 + __t80;
            let __t82: ::routh::__private::f64 = __t76 * __t81;
            let __t84: ::routh::__private::f64 = __t75 - __t82;
            let __t85: ::routh::__private::f64 = __t52 + __t84;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t124: ::routh::__private::f64 = __v0 * __t91;
            let __t125: ::routh::__private::f64 = __v1 * __t95;
            let __t126: ::routh::__private::f64 = __v2 * __t99;
            let __t127: ::routh::__private::f64 = __t124 + __t125;
            let __t128: ::routh::__private::f64 = __t126 + __t127;
            let __t130: ::routh::__private::f64 = __t128 - __t85;
            __t130
        }
        #[inline]
        fn cyclic_momentum(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t131: ::routh::__private::f64 = __v3 * __t91;
            let __t132: ::routh::__private::f64 = __v4 * __t95;
            let __t133: ::routh::__private::f64 = __v5 * __t99;
            let __t134: ::routh::__private::f64 = __t131 + __t132;
            let __t135: ::routh::__private::f64 = __t133 + __t134;
            __t135
        }
    }
    #[automatically_derived]
    impl ::routh::__private::Routhian for Gyrostat {
        #[inline]
        fn psi_dot(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t131: ::routh::__private::f64 = __v3 * __t91;
            let __t132: ::routh::__private::f64 = __v4 * __t95;
            let __t133: ::routh::__private::f64 = __v5 * __t99;
            let __t134: ::routh::__private::f64 = __t131 + __t132;
            let __t135: ::routh::__private::f64 = __t133 + __t134;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t158: ::routh::__private::f64 = __v6 - __t135;
            let __t160: ::routh::__private::f64 = __t158 / __t155;
            __t160
        }
        #[inline]
        fn routhian(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __v25: ::routh::__private::f64 = self.com[0usize];
            let __v26: ::routh::__private::f64 = self.com[1usize];
            let __v27: ::routh::__private::f64 = self.com[2usize];
            let __v28: ::routh::__private::f64 = self.mass;
            let __v29: ::routh::__private::f64 = self.g;
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v0 * __t36;
            let __t48: ::routh::__private::f64 = __v1 * __t41;
            let __t49: ::routh::__private::f64 = __v2 * __t46;
            let __t50: ::routh::__private::f64 = __t47 + __t48;
            let __t51: ::routh::__private::f64 = __t49 + __t50;
            let __t52: ::routh::__private::f64 = 0.5f64 * __t51;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t71: ::routh::__private::f64 = __v0 * __t68;
            let __t72: ::routh::__private::f64 = __v1 * __t69;
            let __t73: ::routh::__private::f64 = __v2 * __t70;
            let __t74: ::routh::__private::f64 = __t71 + __t72;
            let __t75: ::routh::__private::f64 = __t73 + __t74;
            let __t76: ::routh::__private::f64 = __v28 * __v29;
            let __t77: ::routh::__private::f64 = __v3 * __v25;
            let __t78: ::routh::__private::f64 = __v4 * __v26;
            let __t79: ::routh::__private::f64 = __v5 * __v27;
            let __t80: ::routh::__private::f64 = __t77 + __t78;
            let __t81: ::routh::__private::f64 = __t79 + __t80;
            let __t82: ::routh::__private::f64 = __t76 * __t81;
            let __t84: ::routh::__private::f64 = __t75 - __t82;
            let __t85: ::routh::__private::f64 = __t52 + __t84;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t131: ::routh::__private::f64 = __v3 * __t91;
            let __t132: ::routh::__private::f64 = __v4 * __t95;
            let __t133: ::routh::__private::f64 = __v5 * __t99;
            let __t134: ::routh::__private::f64 = __t131 + __t132;
            let __t135: ::routh::__private::f64 = __t133 + __t134;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t158: ::routh::__private::f64 = __v6 - __t135;
            let __t160: ::routh::__private::f64 = __t158 / __t155;
            let __t162: ::routh::__private::f64 = __t158 * __t160;
            let __t165: ::routh::__private::f64 = (-0.5f64) * __t162;
            let __t166: ::routh::__private::f64 = __t85 + __t165;
            __t166
        }
        #[inline]
        fn dr_domega(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t131: ::routh::__private::f64 = __v3 * __t91;
            let __t132: ::routh::__private::f64 = __v4 * __t95;
            let __t133: ::routh::__private::f64 = __v5 * __t99;
            let __t134: ::routh::__private::f64 = __t131 + __t132;
            let __t135: ::routh::__private::f64 = __t133 + __t134;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t158: ::routh::__private::f64 = __v6 - __t135;
            let __t160: ::routh::__private::f64 = __t158 / __t155;
            let __t191: ::routh::__private::f64 = __t140 * __t160;
            let __t192: ::routh::__private::f64 = __t145 * __t160;
            let __t193: ::routh::__private::f64 = __t150 * __t160;
            let __t197: ::routh::__private::f64 = __t91 + __t191;
            let __t198: ::routh::__private::f64 = __t95 + __t192;
            let __t199: ::routh::__private::f64 = __t99 + __t193;
            ::routh::__private::Vector3::new(__t197, __t198, __t199)
        }
        #[inline]
        fn dr_dgamma(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __v25: ::routh::__private::f64 = self.com[0usize];
            let __v26: ::routh::__private::f64 = self.com[1usize];
            let __v27: ::routh::__private::f64 = self.com[2usize];
            let __v28: ::routh::__private::f64 = self.mass;
            let __v29: ::routh::__private::f64 = self.g;
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t76: ::routh::__private::f64 = __v28 * __v29;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t100: ::routh::__private::f64 = __v25 * __t76;
            let __t102: ::routh::__private::f64 = __v1 * __v19;
            let __t103: ::routh::__private::f64 = __v0 * __v16;
            let __t104: ::routh::__private::f64 = __t102 + __t103;
            let __t105: ::routh::__private::f64 = __v2 * __v22;
            let __t106: ::routh::__private::f64 = __t104 + __t105;
            let __t107: ::routh::__private::f64 = __t106 - __t100;
            let __t108: ::routh::__private::f64 = __v26 * __t76;
            let __t110: ::routh::__private::f64 = __v1 * __v20;
            let __t111: ::routh::__private::f64 = __v0 * __v17;
            let __t112: ::routh::__private::f64 = __t110 + __t111;
            let __t113: ::routh::__private::f64 = __v2 * __v23;
            let __t114: ::routh::__private::f64 = __t112 + __t113;
            let __t115: ::routh::__private::f64 = __t114 - __t108;
            let __t116: ::routh::__private::f64 = __v27 * __t76;
            let __t118: ::routh::__private::f64 = __v1 * __v21;
            let __t119: ::routh::__private::f64 = __v0 * __v18;
            let __t120: ::routh::__private::f64 = __t118 + __t119;
            let __t121: ::routh::__private::f64 = __v2 * __v24;
            let __t122: ::routh::__private::f64 = __t120 + __t121;
            let __t123: ::routh::__private::f64 = __t122 - __t116;
            let __t131: ::routh::__private::f64 = __v3 * __t91;
            let __t132: ::routh::__private::f64 = __v4 * __t95;
            let __t133: ::routh::__private::f64 = __v5 * __t99;
            let __t134: ::routh::__private::f64 = __t131 + __t132;
            let __t135: ::routh::__private::f64 = __t133 + __t134;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t158: ::routh::__private::f64 = __v6 - __t135;
            let __t160: ::routh::__private::f64 = __t158 / __t155;
            let __t167: ::routh::__private::f64 = __v4 * __v19;
            let __t168: ::routh::__private::f64 = __t53 + __t91;
            let __t169: ::routh::__private::f64 = __t167 + __t168;
            let __t170: ::routh::__private::f64 = __v5 * __v22;
            let __t171: ::routh::__private::f64 = __t169 + __t170;
            let __t172: ::routh::__private::f64 = __t59 + __t95;
            let __t173: ::routh::__private::f64 = __v3 * __v17;
            let __t174: ::routh::__private::f64 = __t172 + __t173;
            let __t175: ::routh::__private::f64 = __v5 * __v23;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v4 * __v21;
            let __t178: ::routh::__private::f64 = __v3 * __v18;
            let __t179: ::routh::__private::f64 = __t177 + __t178;
            let __t180: ::routh::__private::f64 = __t65 + __t99;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t191: ::routh::__private::f64 = __t140 * __t160;
            let __t192: ::routh::__private::f64 = __t145 * __t160;
            let __t193: ::routh::__private::f64 = __t150 * __t160;
            let __t194: ::routh::__private::f64 = __t171 + __t191;
            let __t195: ::routh::__private::f64 = __t176 + __t192;
            let __t196: ::routh::__private::f64 = __t181 + __t193;
            let __t200: ::routh::__private::f64 = __t160 * __t194;
            let __t201: ::routh::__private::f64 = __t107 + __t200;
            let __t202: ::routh::__private::f64 = __t160 * __t195;
            let __t203: ::routh::__private::f64 = __t115 + __t202;
            let __t204: ::routh::__private::f64 = __t160 * __t196;
            let __t205: ::routh::__private::f64 = __t123 + __t204;
            ::routh::__private::Vector3::new(__t201, __t203, __t205)
        }
        #[inline]
        fn dr_dp(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t131: ::routh::__private::f64 = __v3 * __t91;
            let __t132: ::routh::__private::f64 = __v4 * __t95;
            let __t133: ::routh::__private::f64 = __v5 * __t99;
            let __t134: ::routh::__private::f64 = __t131 + __t132;
            let __t135: ::routh::__private::f64 = __t133 + __t134;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t158: ::routh::__private::f64 = __v6 - __t135;
            let __t160: ::routh::__private::f64 = __t158 / __t155;
            let __t311: ::routh::__private::f64 = -__t160;
            __t311
        }
        #[inline]
        fn d2r_domega2(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t159: ::routh::__private::f64 = 1.0f64 / __t155;
            let __t209: ::routh::__private::f64 = __t140 * __t159;
            let __t210: ::routh::__private::f64 = __t145 * __t159;
            let __t211: ::routh::__private::f64 = __t150 * __t159;
            let __t215: ::routh::__private::f64 = __t140 * __t209;
            let __t217: ::routh::__private::f64 = __v7 - __t215;
            let __t218: ::routh::__private::f64 = __t145 * __t209;
            let __t220: ::routh::__private::f64 = __v8 - __t218;
            let __t221: ::routh::__private::f64 = __t150 * __t209;
            let __t223: ::routh::__private::f64 = __v9 - __t221;
            let __t239: ::routh::__private::f64 = __t145 * __t210;
            let __t241: ::routh::__private::f64 = __v10 - __t239;
            let __t242: ::routh::__private::f64 = __t150 * __t210;
            let __t244: ::routh::__private::f64 = __v11 - __t242;
            let __t259: ::routh::__private::f64 = __t150 * __t211;
            let __t261: ::routh::__private::f64 = __v12 - __t259;
            ::routh::__private::Matrix3::new(
                __t217,
                __t220,
                __t223,
                __t220,
                __t241,
                __t244,
                __t223,
                __t244,
                __t261,
            )
        }
        #[inline]
        fn d2r_domega_dgamma(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t131: ::routh::__private::f64 = __v3 * __t91;
            let __t132: ::routh::__private::f64 = __v4 * __t95;
            let __t133: ::routh::__private::f64 = __v5 * __t99;
            let __t134: ::routh::__private::f64 = __t131 + __t132;
            let __t135: ::routh::__private::f64 = __t133 + __t134;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t158: ::routh::__private::f64 = __v6 - __t135;
            let __t159: ::routh::__private::f64 = 1.0f64 / __t155;
            let __t160: ::routh::__private::f64 = __t158 * __t159;
            let __t167: ::routh::__private::f64 = __v4 * __v19;
            let __t168: ::routh::__private::f64 = __t53 + __t91;
            let __t169: ::routh::__private::f64 = __t167 + __t168;
            let __t170: ::routh::__private::f64 = __v5 * __v22;
            let __t171: ::routh::__private::f64 = __t169 + __t170;
            let __t172: ::routh::__private::f64 = __t59 + __t95;
            let __t173: ::routh::__private::f64 = __v3 * __v17;
            let __t174: ::routh::__private::f64 = __t172 + __t173;
            let __t175: ::routh::__private::f64 = __v5 * __v23;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v4 * __v21;
            let __t178: ::routh::__private::f64 = __v3 * __v18;
            let __t179: ::routh::__private::f64 = __t177 + __t178;
            let __t180: ::routh::__private::f64 = __t65 + __t99;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t191: ::routh::__private::f64 = __t140 * __t160;
            let __t192: ::routh::__private::f64 = __t145 * __t160;
            let __t193: ::routh::__private::f64 = __t150 * __t160;
            let __t194: ::routh::__private::f64 = __t171 + __t191;
            let __t195: ::routh::__private::f64 = __t176 + __t192;
            let __t196: ::routh::__private::f64 = __t181 + __t193;
            let __t206: ::routh::__private::f64 = __t191 + __t194;
            let __t207: ::routh::__private::f64 = __t192 + __t195;
            let __t208: ::routh::__private::f64 = __t193 + __t196;
            let __t209: ::routh::__private::f64 = __t140 * __t159;
            let __t210: ::routh::__private::f64 = __t145 * __t159;
            let __t211: ::routh::__private::f64 = __t150 * __t159;
            let __t224: ::routh::__private::f64 = __v7 * __t160;
            let __t225: ::routh::__private::f64 = __v16 + __t224;
            let __t226: ::routh::__private::f64 = __t206 * __t209;
            let __t228: ::routh::__private::f64 = __t225 - __t226;
            let __t229: ::routh::__private::f64 = __v8 * __t160;
            let __t230: ::routh::__private::f64 = __v17 + __t229;
            let __t231: ::routh::__private::f64 = __t207 * __t209;
            let __t233: ::routh::__private::f64 = __t230 - __t231;
            let __t234: ::routh::__private::f64 = __v9 * __t160;
            let __t235: ::routh::__private::f64 = __v18 + __t234;
            let __t236: ::routh::__private::f64 = __t208 * __t209;
            let __t238: ::routh::__private::f64 = __t235 - __t236;
            let __t245: ::routh::__private::f64 = __v19 + __t229;
            let __t246: ::routh::__private::f64 = __t206 * __t210;
            let __t248: ::routh::__private::f64 = __t245 - __t246;
            let __t249: ::routh::__private::f64 = __v10 * __t160;
            let __t250: ::routh::__private::f64 = __v20 + __t249;
            let __t251: ::routh::__private::f64 = __t207 * __t210;
            let __t253: ::routh::__private::f64 = __t250 - __t251;
            let __t254: ::routh::__private::f64 = __v11 * __t160;
            let __t255: ::routh::__private::f64 = __v21 + __t254;
            let __t256: ::routh::__private::f64 = __t208 * __t210;
            let __t258: ::routh::__private::f64 = __t255 - __t256;
            let __t262: ::routh::__private::f64 = __v22 + __t234;
            let __t263: ::routh::__private::f64 = __t206 * __t211;
            let __t265: ::routh::__private::f64 = __t262 - __t263;
            let __t266: ::routh::__private::f64 = __v23 + __t254;
            let __t267: ::routh::__private::f64 = __t207 * __t211;
            let __t269: ::routh::__private::f64 = __t266 - __t267;
            let __t270: ::routh::__private::f64 = __v12 * __t160;
            let __t271: ::routh::__private::f64 = __v24 + __t270;
            let __t272: ::routh::__private::f64 = __t208 * __t211;
            let __t274: ::routh::__private::f64 = __t271 - __t272;
            ::routh::__private::Matrix3::new(
                __t228,
                __t233,
                __t238,
                __t248,
                __t253,
                __t258,
                __t265,
                __t269,
                __t274,
            )
        }
        #[inline]
        fn d2r_dgamma2(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t131: ::routh::__private::f64 = __v3 * __t91;
            let __t132: ::routh::__private::f64 = __v4 * __t95;
            let __t133: ::routh::__private::f64 = __v5 * __t99;
            let __t134: ::routh::__private::f64 = __t131 + __t132;
            let __t135: ::routh::__private::f64 = __t133 + __t134;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t158: ::routh::__private::f64 = __v6 - __t135;
            let __t159: ::routh::__private::f64 = 1.0f64 / __t155;
            let __t160: ::routh::__private::f64 = __t158 * __t159;
            let __t167: ::routh::__private::f64 = __v4 * __v19;
            let __t168: ::routh::__private::f64 = __t53 + __t91;
            let __t169: ::routh::__private::f64 = __t167 + __t168;
            let __t170: ::routh::__private::f64 = __v5 * __v22;
            let __t171: ::routh::__private::f64 = __t169 + __t170;
            let __t172: ::routh::__private::f64 = __t59 + __t95;
            let __t173: ::routh::__private::f64 = __v3 * __v17;
            let __t174: ::routh::__private::f64 = __t172 + __t173;
            let __t175: ::routh::__private::f64 = __v5 * __v23;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v4 * __v21;
            let __t178: ::routh::__private::f64 = __v3 * __v18;
            let __t179: ::routh::__private::f64 = __t177 + __t178;
            let __t180: ::routh::__private::f64 = __t65 + __t99;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t191: ::routh::__private::f64 = __t140 * __t160;
            let __t192: ::routh::__private::f64 = __t145 * __t160;
            let __t193: ::routh::__private::f64 = __t150 * __t160;
            let __t194: ::routh::__private::f64 = __t171 + __t191;
            let __t195: ::routh::__private::f64 = __t176 + __t192;
            let __t196: ::routh::__private::f64 = __t181 + __t193;
            let __t206: ::routh::__private::f64 = __t191 + __t194;
            let __t207: ::routh::__private::f64 = __t192 + __t195;
            let __t208: ::routh::__private::f64 = __t193 + __t196;
            let __t212: ::routh::__private::f64 = __t159 * __t206;
            let __t213: ::routh::__private::f64 = __t159 * __t207;
            let __t214: ::routh::__private::f64 = __t159 * __t208;
            let __t224: ::routh::__private::f64 = __v7 * __t160;
            let __t225: ::routh::__private::f64 = __v16 + __t224;
            let __t229: ::routh::__private::f64 = __v8 * __t160;
            let __t230: ::routh::__private::f64 = __v17 + __t229;
            let __t234: ::routh::__private::f64 = __v9 * __t160;
            let __t235: ::routh::__private::f64 = __v18 + __t234;
            let __t249: ::routh::__private::f64 = __v10 * __t160;
            let __t250: ::routh::__private::f64 = __v20 + __t249;
            let __t254: ::routh::__private::f64 = __v11 * __t160;
            let __t255: ::routh::__private::f64 = __v21 + __t254;
            let __t270: ::routh::__private::f64 = __v12 * __t160;
            let __t271: ::routh::__private::f64 = __v24 + __t270;
            let __t276: ::routh::__private::f64 = __v16 + __t225;
            let __t277: ::routh::__private::f64 = __t160 * __t276;
            let __t278: ::routh::__private::f64 = __t206 * __t212;
            let __t280: ::routh::__private::f64 = __t277 - __t278;
            let __t282: ::routh::__private::f64 = __v19 + __t230;
            let __t283: ::routh::__private::f64 = __t160 * __t282;
            let __t284: ::routh::__private::f64 = __t207 * __t212;
            let __t286: ::routh::__private::f64 = __t283 - __t284;
            let __t288: ::routh::__private::f64 = __v22 + __t235;
            let __t289: ::routh::__private::f64 = __t160 * __t288;
            let __t290: ::routh::__private::f64 = __t208 * __t212;
            let __t292: ::routh::__private::f64 = __t289 - __t290;
            let __t294: ::routh::__private::f64 = __v20 + __t250;
            let __t295: ::routh::__private::f64 = __t160 * __t294;
            let __t296: ::routh::__private::f64 = __t207 * __t213;
            let __t298: ::routh::__private::f64 = __t295 - __t296;
            let __t300: ::routh::__private::f64 = __v23 + __t255;
            let __t301: ::routh::__private::f64 = __t160 * __t300;
            let __t302: ::routh::__private::f64 = __t208 * __t213;
            let __t304: ::routh::__private::f64 = __t301 - __t302;
            let __t306: ::routh::__private::f64 = __v24 + __t271;
            let __t307: ::routh::__private::f64 = __t160 * __t306;
            let __t308: ::routh::__private::f64 = __t208 * __t214;
            let __t310: ::routh::__private::f64 = __t307 - __t308;
            ::routh::__private::Matrix3::new(
                __t280,
                __t286,
                __t292,
                __t286,
                __t298,
                __t304,
                __t292,
                __t304,
                __t310,
            )
        }
        #[inline]
        fn amended_potential(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __v25: ::routh::__private::f64 = self.com[0usize];
            let __v26: ::routh::__private::f64 = self.com[1usize];
            let __v27: ::routh::__private::f64 = self.com[2usize];
            let __v28: ::routh::__private::f64 = self.mass;
            let __v29: ::routh::__private::f64 = self.g;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t76: ::routh::__private::f64 = __v28 * __v29;
            let __t77: ::routh::__private::f64 = __v3 * __v25;
            let __t78: ::routh::__private::f64 = __v4 * __v26;
            let __t79: ::routh::__private::f64 = __v5 * __v27;
            let __t80: ::routh::__private::f64 = __t77 + __t78;
            let __t81: ::routh::__private::f64 = __t79 + __t80;
            let __t82: ::routh::__private::f64 = __t76 * __t81;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t312: ::routh::__private::f64 = __v3 * __t68;
            let __t313: ::routh::__private::f64 = __v4 * __t69;
            let __t314: ::routh::__private::f64 = __v5 * __t70;
            let __t315: ::routh::__private::f64 = __t312 + __t313;
            let __t316: ::routh::__private::f64 = __t314 + __t315;
            let __t318: ::routh::__private::f64 = __v6 - __t316;
            let __t319: ::routh::__private::f64 = __t318 / __t155;
            let __t321: ::routh::__private::f64 = __t318 * __t319;
            let __t323: ::routh::__private::f64 = (-0.5f64) * __t321;
            let __t324: ::routh::__private::f64 = __t323 - __t82;
            let __t429: ::routh::__private::f64 = -__t324;
            __t429
        }
        #[inline]
        fn bundle(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::RouthBundle {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __v25: ::routh::__private::f64 = self.com[0usize];
            let __v26: ::routh::__private::f64 = self.com[1usize];
            let __v27: ::routh::__private::f64 = self.com[2usize];
            let __v28: ::routh::__private::f64 = self.mass;
            let __v29: ::routh::__private::f64 = self.g;
            let __t32: ::routh::__private::f64 = __v0 * __v7;
            let __t33: ::routh::__private::f64 = __v1 * __v8;
            let __t34: ::routh::__private::f64 = __v2 * __v9;
            let __t35: ::routh::__private::f64 = __t32 + __t33;
            let __t36: ::routh::__private::f64 = __t34 + __t35;
            let __t37: ::routh::__private::f64 = __v0 * __v8;
            let __t38: ::routh::__private::f64 = __v1 * __v10;
            let __t39: ::routh::__private::f64 = __v2 * __v11;
            let __t40: ::routh::__private::f64 = __t37 + __t38;
            let __t41: ::routh::__private::f64 = __t39 + __t40;
            let __t42: ::routh::__private::f64 = __v0 * __v9;
            let __t43: ::routh::__private::f64 = __v1 * __v11;
            let __t44: ::routh::__private::f64 = __v2 * __v12;
            let __t45: ::routh::__private::f64 = __t42 + __t43;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v0 * __t36;
            let __t48: ::routh::__private::f64 = __v1 * __t41;
            let __t49: ::routh::__private::f64 = __v2 * __t46;
            let __t50: ::routh::__private::f64 = __t47 + __t48;
            let __t51: ::routh::__private::f64 = __t49 + __t50;
            let __t52: ::routh::__private::f64 = 0.5f64 * __t51;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t71: ::routh::__private::f64 = __v0 * __t68;
            let __t72: ::routh::__private::f64 = __v1 * __t69;
            let __t73: ::routh::__private::f64 = __v2 * __t70;
            let __t74: ::routh::__private::f64 = __t71 + __t72;
            let __t75: ::routh::__private::f64 = __t73 + __t74;
            let __t76: ::routh::__private::f64 = __v28 * __v29;
            let __t77: ::routh::__private::f64 = __v3 * __v25;
            let __t78: ::routh::__private::f64 = __v4 * __v26;
            let __t79: ::routh::__private::f64 = __v5 * __v27;
            let __t80: ::routh::__private::f64 = __t77 + __t78;
            let __t81: ::routh::__private::f64 = __t79 + __t80;
            let __t82: ::routh::__private::f64 = __t76 * __t81;
            let __t84: ::routh::__private::f64 = __t75 - __t82;
            let __t85: ::routh::__private::f64 = __t52 + __t84;
            let __t91: ::routh::__private::f64 = __t36 + __t68;
            let __t95: ::routh::__private::f64 = __t41 + __t69;
            let __t99: ::routh::__private::f64 = __t46 + __t70;
            let __t100: ::routh::__private::f64 = __v25 * __t76;
            let __t102: ::routh::__private::f64 = __v1 * __v19;
            let __t103: ::routh::__private::f64 = __v0 * __v16;
            let __t104: ::routh::__private::f64 = __t102 + __t103;
            let __t105: ::routh::__private::f64 = __v2 * __v22;
            let __t106: ::routh::__private::f64 = __t104 + __t105;
            let __t107: ::routh::__private::f64 = __t106 - __t100;
            let __t108: ::routh::__private::f64 = __v26 * __t76;
            let __t110: ::routh::__private::f64 = __v1 * __v20;
            let __t111: ::routh::__private::f64 = __v0 * __v17;
            let __t112: ::routh::__private::f64 = __t110 + __t111;
            let __t113: ::routh::__private::f64 = __v2 * __v23;
            let __t114: ::routh::__private::f64 = __t112 + __t113;
            let __t115: ::routh::__private::f64 = __t114 - __t108;
            let __t116: ::routh::__private::f64 = __v27 * __t76;
            let __t118: ::routh::__private::f64 = __v1 * __v21;
            let __t119: ::routh::__private::f64 = __v0 * __v18;
            let __t120: ::routh::__private::f64 = __t118 + __t119;
            let __t121: ::routh::__private::f64 = __v2 * __v24;
            let __t122: ::routh::__private::f64 = __t120 + __t121;
            let __t123: ::routh::__private::f64 = __t122 - __t116;
            let __t131: ::routh::__private::f64 = __v3 * __t91;
            let __t132: ::routh::__private::f64 = __v4 * __t95;
            let __t133: ::routh::__private::f64 = __v5 * __t99;
            let __t134: ::routh::__private::f64 = __t131 + __t132;
            let __t135: ::routh::__private::f64 = __t133 + __t134;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t158: ::routh::__private::f64 = __v6 - __t135;
            let __t159: ::routh::__private::f64 = 1.0f64 / __t155;
            let __t160: ::routh::__private::f64 = __t158 * __t159;
            let __t162: ::routh::__private::f64 = __t158 * __t160;
            let __t165: ::routh::__private::f64 = (-0.5f64) * __t162;
            let __t166: ::routh::__private::f64 = __t85 + __t165;
            let __t167: ::routh::__private::f64 = __v4 * __v19;
            let __t168: ::routh::__private::f64 = __t53 + __t91;
            let __t169: ::routh::__private::f64 = __t167 + __t168;
            let __t170: ::routh::__private::f64 = __v5 * __v22;
            let __t171: ::routh::__private::f64 = __t169 + __t170;
            let __t172: ::routh::__private::f64 = __t59 + __t95;
            let __t173: ::routh::__private::f64 = __v3 * __v17;
            let __t174: ::routh::__private::f64 = __t172 + __t173;
            let __t175: ::routh::__private::f64 = __v5 * __v23;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v4 * __v21;
            let __t178: ::routh::__private::f64 = __v3 * __v18;
            let __t179: ::routh::__private::f64 = __t177 + __t178;
            let __t180: ::routh::__private::f64 = __t65 + __t99;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t191: ::routh::__private::f64 = __t140 * __t160;
            let __t192: ::routh::__private::f64 = __t145 * __t160;
            let __t193: ::routh::__private::f64 = __t150 * __t160;
            let __t194: ::routh::__private::f64 = __t171 + __t191;
            let __t195: ::routh::__private::f64 = __t176 + __t192;
            let __t196: ::routh::__private::f64 = __t181 + __t193;
            let __t197: ::routh::__private::f64 = __t91 + __t191;
            let __t198: ::routh::__private::f64 = __t95 + __t192;
            let __t199: ::routh::__private::f64 = __t99 + __t193;
            let __t200: ::routh::__private::f64 = __t160 * __t194;
            let __t201: ::routh::__private::f64 = __t107 + __t200;
            let __t202: ::routh::__private::f64 = __t160 * __t195;
            let __t203: ::routh::__private::f64 = __t115 + __t202;
            let __t204: ::routh::__private::f64 = __t160 * __t196;
            let __t205: ::routh::__private::f64 = __t123 + __t204;
            let __t206: ::routh::__private::f64 = __t191 + __t194;
            let __t207: ::routh::__private::f64 = __t192 + __t195;
            let __t208: ::routh::__private::f64 = __t193 + __t196;
            let __t209: ::routh::__private::f64 = __t140 * __t159;
            let __t210: ::routh::__private::f64 = __t145 * __t159;
            let __t211: ::routh::__private::f64 = __t150 * __t159;
            let __t212: ::routh::__private::f64 = __t159 * __t206;
            let __t213: ::routh::__private::f64 = __t159 * __t207;
            let __t214: ::routh::__private::f64 = __t159 * __t208;
            let __t215: ::routh::__private::f64 = __t140 * __t209;
            let __t217: ::routh::__private::f64 = __v7 - __t215;
            let __t218: ::routh::__private::f64 = __t145 * __t209;
            let __t220: ::routh::__private::f64 = __v8 - __t218;
            let __t221: ::routh::__private::f64 = __t150 * __t209;
            let __t223: ::routh::__private::f64 = __v9 - __t221;
            let __t224: ::routh::__private::f64 = __v7 * __t160;
            let __t225: ::routh::__private::f64 = __v16 + __t224;
            let __t226: ::routh::__private::f64 = __t206 * __t209;
            let __t228: ::routh::__private::f64 = __t225 - __t226;
            let __t229: ::routh::__private::f64 = __v8 * __t160;
            let __t230: ::routh::__private::f64 = __v17 + __t229;
            let __t231: ::routh::__private::f64 = __t207 * __t209;
            let __t233: ::routh::__private::f64 = __t230 - __t231;
            let __t234: ::routh::__private::f64 = __v9 * __t160;
            let __t235: ::routh::__private::f64 = __v18 + __t234;
            let __t236: ::routh::__private::f64 = __t208 * __t209;
            let __t238: ::routh::__private::f64 = __t235 - __t236;
            let __t239: ::routh::__private::f64 = __t145 * __t210;
            let __t241: ::routh::__private::f64 = __v10 - __t239;
            let __t242: ::routh::__private::f64 = __t150 * __t210;
            let __t244: ::routh::__private::f64 = __v11 - __t242;
            let __t245: ::routh::__private::f64 = __v19 + __t229;
            let __t246: ::routh::__private::f64 = __t206 * __t210;
            let __t248: ::routh::__private::f64 = __t245 - __t246;
            let __t249: ::routh::__private::f64 = __v10 * __t160;
            let __t250: ::routh::__private::f64 = __v20 + __t249;
            let __t251: ::routh::__private::f64 = __t207 * __t210;
            let __t253: ::routh::__private::f64 = __t250 - __t251;
            let __t254: ::routh::__private::f64 = __v11 * __t160;
            let __t255: ::routh::__private::f64 = __v21 + __t254;
            let __t256: ::routh::__private::f64 = __t208 * __t210;
            let __t258: ::routh::__private::f64 = __t255 - __t256;
            let __t259: ::routh::__private::f64 = __t150 * __t211;
            let __t261: ::routh::__private::f64 = __v12 - __t259;
            let __t262: ::routh::__private::f64 = __v22 + __t234;
            let __t263: ::routh::__private::f64 = __t206 * __t211;
            let __t265: ::routh::__private::f64 = __t262 - __t263;
            let __t266: ::routh::__private::f64 = __v23 + __t254;
            let __t267: ::routh::__private::f64 = __t207 * __t211;
            let __t269: ::routh::__private::f64 = __t266 - __t267;
            let __t270: ::routh::__private::f64 = __v12 * __t160;
            let __t271: ::routh::__private::f64 = __v24 + __t270;
            let __t272: ::routh::__private::f64 = __t208 * __t211;
            let __t274: ::routh::__private::f64 = __t271 - __t272;
            let __t276: ::routh::__private::f64 = __v16 + __t225;
            let __t277: ::routh::__private::f64 = __t160 * __t276;
            let __t278: ::routh::__private::f64 = __t206 * __t212;
            let __t280: ::routh::__private::f64 = __t277 - __t278;
            let __t282: ::routh::__private::f64 = __v19 + __t230;
            let __t283: ::routh::__private::f64 = __t160 * __t282;
            let __t284: ::routh::__private::f64 = __t207 * __t212;
            let __t286: ::routh::__private::f64 = __t283 - __t284;
            let __t288: ::routh::__private::f64 = __v22 + __t235;
            let __t289: ::routh::__private::f64 = __t160 * __t288;
            let __t290: ::routh::__private::f64 = __t208 * __t212;
            let __t292: ::routh::__private::f64 = __t289 - __t290;
            let __t294: ::routh::__private::f64 = __v20 + __t250;
            let __t295: ::routh::__private::f64 = __t160 * __t294;
            let __t296: ::routh::__private::f64 = __t207 * __t213;
            let __t298: ::routh::__private::f64 = __t295 - __t296;
            let __t300: ::routh::__private::f64 = __v23 + __t255;
            let __t301: ::routh::__private::f64 = __t160 * __t300;
            let __t302: ::routh::__private::f64 = __t208 * __t213;
            let __t304: ::routh::__private::f64 = __t301 - __t302;
            let __t306: ::routh::__private::f64 = __v24 + __t271;
            let __t307: ::routh::__private::f64 = __t160 * __t306;
            let __t308: ::routh::__private::f64 = __t208 * __t214;
            let __t310: ::routh::__private::f64 = __t307 - __t308;
            let __t311: ::routh::__private::f64 = -__t160;
            ::routh::__private::RouthBundle {
                routhian: __t166,
                psi_dot: __t160,
                dr_domega: ::routh::__private::Vector3::new(__t197, __t198, __t199),
                dr_dgamma: ::routh::__private::Vector3::new(__t201, __t203, __t205),
                dr_dp: __t311,
                d2r_domega2: ::routh::__private::Matrix3::new(
                    __t217,
                    __t220,
                    __t223,
                    __t220,
                    __t241,
                    __t244,
                    __t223,
                    __t244,
                    __t261,
                ),
                d2r_domega_dgamma: ::routh::__private::Matrix3::new(
                    __t228,
                    __t233,
                    __t238,
                    __t248,
                    __t253,
                    __t258,
                    __t265,
                    __t269,
                    __t274,
                ),
                d2r_dgamma2: ::routh::__private::Matrix3::new(
                    __t280,
                    __t286,
                    __t292,
                    __t286,
                    __t298,
                    __t304,
                    __t292,
                    __t304,
                    __t310,
                ),
            }
        }
        #[inline]
        fn gyroscopic_system(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::GyroscopicSystem {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.inertia[(0usize, 0usize)];
            let __v8: ::routh::__private::f64 = self.inertia[(0usize, 1usize)];
            let __v9: ::routh::__private::f64 = self.inertia[(0usize, 2usize)];
            let __v10: ::routh::__private::f64 = self.inertia[(1usize, 1usize)];
            let __v11: ::routh::__private::f64 = self.inertia[(1usize, 2usize)];
            let __v12: ::routh::__private::f64 = self.inertia[(2usize, 2usize)];
            let __v13: ::routh::__private::f64 = self.rotor[0usize];
            let __v14: ::routh::__private::f64 = self.rotor[1usize];
            let __v15: ::routh::__private::f64 = self.rotor[2usize];
            let __v16: ::routh::__private::f64 = self.coupling[(0usize, 0usize)];
            let __v17: ::routh::__private::f64 = self.coupling[(0usize, 1usize)];
            let __v18: ::routh::__private::f64 = self.coupling[(0usize, 2usize)];
            let __v19: ::routh::__private::f64 = self.coupling[(1usize, 0usize)];
            let __v20: ::routh::__private::f64 = self.coupling[(1usize, 1usize)];
            let __v21: ::routh::__private::f64 = self.coupling[(1usize, 2usize)];
            let __v22: ::routh::__private::f64 = self.coupling[(2usize, 0usize)];
            let __v23: ::routh::__private::f64 = self.coupling[(2usize, 1usize)];
            let __v24: ::routh::__private::f64 = self.coupling[(2usize, 2usize)];
            let __v25: ::routh::__private::f64 = self.com[0usize];
            let __v26: ::routh::__private::f64 = self.com[1usize];
            let __v27: ::routh::__private::f64 = self.com[2usize];
            let __v28: ::routh::__private::f64 = self.mass;
            let __v29: ::routh::__private::f64 = self.g;
            let __t53: ::routh::__private::f64 = __v3 * __v16;
            let __t54: ::routh::__private::f64 = __v4 * __v17;
            let __t55: ::routh::__private::f64 = __v5 * __v18;
            let __t56: ::routh::__private::f64 = __t53 + __t54;
            let __t57: ::routh::__private::f64 = __t55 + __t56;
            let __t58: ::routh::__private::f64 = __v3 * __v19;
            let __t59: ::routh::__private::f64 = __v4 * __v20;
            let __t60: ::routh::__private::f64 = __v5 * __v21;
            let __t61: ::routh::__private::f64 = __t58 + __t59;
            let __t62: ::routh::__private::f64 = __t60 + __t61;
            let __t63: ::routh::__private::f64 = __v3 * __v22;
            let __t64: ::routh::__private::f64 = __v4 * __v23;
            let __t65: ::routh::__private::f64 = __v5 * __v24;
            let __t66: ::routh::__private::f64 = __t63 + __t64;
            let __t67: ::routh::__private::f64 = __t65 + __t66;
            let __t68: ::routh::__private::f64 = __v13 + __t57;
            let __t69: ::routh::__private::f64 = __v14 + __t62;
            let __t70: ::routh::__private::f64 = __v15 + __t67;
            let __t76: ::routh::__private::f64 = __v28 * __v29;
            let __t100: ::routh::__private::f64 = __v25 * __t76;
            let __t108: ::routh::__private::f64 = __v26 * __t76;
            let __t116: ::routh::__private::f64 = __v27 * __t76;
            let __t136: ::routh::__private::f64 = __v3 * __v7;
            let __t137: ::routh::__private::f64 = __v4 * __v8;
            let __t138: ::routh::__private::f64 = __v5 * __v9;
            let __t139: ::routh::__private::f64 = __t136 + __t137;
            let __t140: ::routh::__private::f64 = __t138 + __t139;
            let __t141: ::routh::__private::f64 = __v3 * __v8;
            let __t142: ::routh::__private::f64 = __v4 * __v10;
            let __t143: ::routh::__private::f64 = __v5 * __v11;
            let __t144: ::routh::__private::f64 = __t141 + __t142;
            let __t145: ::routh::__private::f64 = __t143 + __t144;
            let __t146: ::routh::__private::f64 = __v3 * __v9;
            let __t147: ::routh::__private::f64 = __v4 * __v11;
            let __t148: ::routh::__private::f64 = __v5 * __v12;
            let __t149: ::routh::__private::f64 = __t146 + __t147;
            let __t150: ::routh::__private::f64 = __t148 + __t149;
            let __t151: ::routh::__private::f64 = __v3 * __t140;
            let __t152: ::routh::__private::f64 = __v4 * __t145;
            let __t153: ::routh::__private::f64 = __v5 * __t150;
            let __t154: ::routh::__private::f64 = __t151 + __t152;
            let __t155: ::routh::__private::f64 = __t153 + __t154;
            let __t159: ::routh::__private::f64 = 1.0f64 / __t155;
            let __t167: ::routh::__private::f64 = __v4 * __v19;
            let __t170: ::routh::__private::f64 = __v5 * __v22;
            let __t173: ::routh::__private::f64 = __v3 * __v17;
            let __t175: ::routh::__private::f64 = __v5 * __v23;
            let __t177: ::routh::__private::f64 = __v4 * __v21;
            let __t178: ::routh::__private::f64 = __v3 * __v18;
            let __t179: ::routh::__private::f64 = __t177 + __t178;
            let __t209: ::routh::__private::f64 = __t140 * __t159;
            let __t210: ::routh::__private::f64 = __t145 * __t159;
            let __t211: ::routh::__private::f64 = __t150 * __t159;
            let __t215: ::routh::__private::f64 = __t140 * __t209;
            let __t217: ::routh::__private::f64 = __v7 - __t215;
            let __t218: ::routh::__private::f64 = __t145 * __t209;
            let __t220: ::routh::__private::f64 = __v8 - __t218;
            let __t221: ::routh::__private::f64 = __t150 * __t209;
            let __t223: ::routh::__private::f64 = __v9 - __t221;
            let __t239: ::routh::__private::f64 = __t145 * __t210;
            let __t241: ::routh::__private::f64 = __v10 - __t239;
            let __t242: ::routh::__private::f64 = __t150 * __t210;
            let __t244: ::routh::__private::f64 = __v11 - __t242;
            let __t259: ::routh::__private::f64 = __t150 * __t211;
            let __t261: ::routh::__private::f64 = __v12 - __t259;
            let __t275: ::routh::__private::f64 = 2f64 * __v16;
            let __t281: ::routh::__private::f64 = __v17 + __v19;
            let __t287: ::routh::__private::f64 = __v18 + __v22;
            let __t293: ::routh::__private::f64 = 2f64 * __v20;
            let __t299: ::routh::__private::f64 = __v21 + __v23;
            let __t305: ::routh::__private::f64 = 2f64 * __v24;
            let __t312: ::routh::__private::f64 = __v3 * __t68;
            let __t313: ::routh::__private::f64 = __v4 * __t69;
            let __t314: ::routh::__private::f64 = __v5 * __t70;
            let __t315: ::routh::__private::f64 = __t312 + __t313;
            let __t316: ::routh::__private::f64 = __t314 + __t315;
            let __t318: ::routh::__private::f64 = __v6 - __t316;
            let __t319: ::routh::__private::f64 = __t159 * __t318;
            let __t325: ::routh::__private::f64 = __t53 + __t68;
            let __t326: ::routh::__private::f64 = __t167 + __t325;
            let __t327: ::routh::__private::f64 = __t170 + __t326;
            let __t328: ::routh::__private::f64 = __t59 + __t69;
            let __t329: ::routh::__private::f64 = __t173 + __t328;
            let __t330: ::routh::__private::f64 = __t175 + __t329;
            let __t331: ::routh::__private::f64 = __t65 + __t70;
            let __t332: ::routh::__private::f64 = __t179 + __t331;
            let __t336: ::routh::__private::f64 = __t140 * __t319;
            let __t337: ::routh::__private::f64 = __t145 * __t319;
            let __t338: ::routh::__private::f64 = __t150 * __t319;
            let __t339: ::routh::__private::f64 = __t327 + __t336;
            let __t340: ::routh::__private::f64 = __t330 + __t337;
            let __t341: ::routh::__private::f64 = __t332 + __t338;
            let __t345: ::routh::__private::f64 = __t319 * __t339;
            let __t346: ::routh::__private::f64 = __t345 - __t100;
            let __t347: ::routh::__private::f64 = __t319 * __t340;
            let __t348: ::routh::__private::f64 = __t347 - __t108;
            let __t349: ::routh::__private::f64 = __t319 * __t341;
            let __t350: ::routh::__private::f64 = __t349 - __t116;
            let __t351: ::routh::__private::f64 = __t336 + __t339;
            let __t352: ::routh::__private::f64 = __t337 + __t340;
            let __t353: ::routh::__private::f64 = __t338 + __t341;
            let __t354: ::routh::__private::f64 = __t159 * __t351;
            let __t355: ::routh::__private::f64 = __t159 * __t352;
            let __t356: ::routh::__private::f64 = __t159 * __t353;
            let __t357: ::routh::__private::f64 = __v7 * __t319;
            let __t358: ::routh::__private::f64 = __v16 + __t357;
            let __t359: ::routh::__private::f64 = __t209 * __t351;
            let __t361: ::routh::__private::f64 = __t358 - __t359;
            let __t362: ::routh::__private::f64 = __v8 * __t319;
            let __t367: ::routh::__private::f64 = __v9 * __t319;
            let __t376: ::routh::__private::f64 = __v10 * __t319;
            let __t377: ::routh::__private::f64 = __v20 + __t376;
            let __t378: ::routh::__private::f64 = __t210 * __t352;
            let __t380: ::routh::__private::f64 = __t377 - __t378;
            let __t381: ::routh::__private::f64 = __v11 * __t319;
            let __t394: ::routh::__private::f64 = __v12 * __t319;
            let __t395: ::routh::__private::f64 = __v24 + __t394;
            let __t396: ::routh::__private::f64 = __t211 * __t353;
            let __t398: ::routh::__private::f64 = __t395 - __t396;
            let __t399: ::routh::__private::f64 = __t275 + __t357;
            let __t400: ::routh::__private::f64 = __t319 * __t399;
            let __t401: ::routh::__private::f64 = __t351 * __t354;
            let __t403: ::routh::__private::f64 = __t400 - __t401;
            let __t404: ::routh::__private::f64 = __t281 + __t362;
            let __t405: ::routh::__private::f64 = __t319 * __t404;
            let __t406: ::routh::__private::f64 = __t352 * __t354;
            let __t408: ::routh::__private::f64 = __t405 - __t406;
            let __t409: ::routh::__private::f64 = __t287 + __t367;
            let __t410: ::routh::__private::f64 = __t319 * __t409;
            let __t411: ::routh::__private::f64 = __t353 * __t354;
            let __t413: ::routh::__private::f64 = __t410 - __t411;
            let __t414: ::routh::__private::f64 = __t293 + __t376;
            let __t415: ::routh::__private::f64 = __t319 * __t414;
            let __t416: ::routh::__private::f64 = __t352 * __t355;
            let __t418: ::routh::__private::f64 = __t415 - __t416;
            let __t419: ::routh::__private::f64 = __t299 + __t381;
            let __t420: ::routh::__private::f64 = __t319 * __t419;
            let __t421: ::routh::__private::f64 = __t353 * __t355;
            let __t423: ::routh::__private::f64 = __t420 - __t421;
            let __t424: ::routh::__private::f64 = __t305 + __t394;
            let __t425: ::routh::__private::f64 = __t319 * __t424;
            let __t426: ::routh::__private::f64 = __t353 * __t356;
            let __t428: ::routh::__private::f64 = __t425 - __t426;
            let __t433: ::routh::__private::f64 = __t361 + __t380;
            let __t434: ::routh::__private::f64 = __t398 + __t433;
            let __t436: ::routh::__private::f64 = __v5 * __t434;
            let __t437: ::routh::__private::f64 = 0.5f64 * __t436;
            let __t438: ::routh::__private::f64 = (-0.5f64) * __t436;
            let __t439: ::routh::__private::f64 = __v4 * __t434;
            let __t440: ::routh::__private::f64 = 0.5f64 * __t439;
            let __t441: ::routh::__private::f64 = __v3 * __t434;
            let __t442: ::routh::__private::f64 = 0.5f64 * __t441;
            let __t443: ::routh::__private::f64 = (-0.5f64) * __t441;
            let __t444: ::routh::__private::f64 = (-0.5f64) * __t439;
            let __t445: ::routh::__private::f64 = __v3 * __t346;
            let __t446: ::routh::__private::f64 = __v4 * __t348;
            let __t447: ::routh::__private::f64 = __v5 * __t350;
            let __t448: ::routh::__private::f64 = __t445 + __t446;
            let __t449: ::routh::__private::f64 = __t447 + __t448;
            let __t451: ::routh::__private::f64 = __t449 - __t403;
            let __t455: ::routh::__private::f64 = __t449 - __t418;
            let __t458: ::routh::__private::f64 = __t449 - __t428;
            let __t459: ::routh::__private::f64 = __v5 * __t408;
            let __t461: ::routh::__private::f64 = __v4 * __t413;
            let __t463: ::routh::__private::f64 = __t461 - __t459;
            let __t464: ::routh::__private::f64 = __v5 * __t455;
            let __t465: ::routh::__private::f64 = __v4 * __t423;
            let __t467: ::routh::__private::f64 = __t464 + __t465;
            let __t468: ::routh::__private::f64 = __v5 * __t423;
            let __t470: ::routh::__private::f64 = __v4 * __t458;
            let __t472: ::routh::__private::f64 = __t468 + __t470;
            let __t474: ::routh::__private::f64 = __v5 * __t451;
            let __t476: ::routh::__private::f64 = __v3 * __t413;
            let __t478: ::routh::__private::f64 = __t474 + __t476;
            let __t480: ::routh::__private::f64 = __v3 * __t423;
            let __t482: ::routh::__private::f64 = __t459 - __t480;
            let __t483: ::routh::__private::f64 = __v5 * __t413;
            let __t485: ::routh::__private::f64 = __v3 * __t458;
            let __t486: ::routh::__private::f64 = __t483 + __t485;
            let __t487: ::routh::__private::f64 = __v4 * __t451;
            let __t488: ::routh::__private::f64 = __v3 * __t408;
            let __t490: ::routh::__private::f64 = __t487 + __t488;
            let __t491: ::routh::__private::f64 = __v4 * __t408;
            let __t493: ::routh::__private::f64 = __v3 * __t455;
            let __t495: ::routh::__private::f64 = __t491 + __t493;
            let __t498: ::routh::__private::f64 = __v5 * __t467;
            let __t499: ::routh::__private::f64 = __v4 * __t472;
            let __t501: ::routh::__private::f64 = __t498 + __t499;
            let __t502: ::routh::__private::f64 = __v5 * __t463;
            let __t504: ::routh::__private::f64 = __v3 * __t472;
            let __t506: ::routh::__private::f64 = __t502 + __t504;
            let __t507: ::routh::__private::f64 = -__t506;
            let __t508: ::routh::__private::f64 = __v4 * __t463;
            let __t509: ::routh::__private::f64 = __v3 * __t467;
            let __t511: ::routh::__private::f64 = __t508 - __t509;
            let __t512: ::routh::__private::f64 = __v5 * __t478;
            let __t514: ::routh::__private::f64 = __v3 * __t486;
            let __t515: ::routh::__private::f64 = __t512 + __t514;
            let __t516: ::routh::__private::f64 = __v4 * __t478;
            let __t518: ::routh::__private::f64 = __v3 * __t482;
            let __t520: ::routh::__private::f64 = __t516 + __t518;
            let __t521: ::routh::__private::f64 = -__t520;
            let __t522: ::routh::__private::f64 = __v4 * __t490;
            let __t523: ::routh::__private::f64 = __v3 * __t495;
            let __t525: ::routh::__private::f64 = __t522 + __t523;
            ::routh::__private::GyroscopicSystem {
                a: ::routh::__private::Matrix3::new(
                    __t217,
                    __t220,
                    __t223,
                    __t220,
                    __t241,
                    __t244,
                    __t223,
                    __t244,
                    __t261,
                ),
                g: ::routh::__private::Matrix3::new(
                    0f64,
                    __t438,
                    __t440,
                    __t437,
                    0f64,
                    __t443,
                    __t444,
                    __t442,
                    0f64,
                ),
                c: ::routh::__private::Matrix3::new(
                    __t501,
                    __t507,
                    __t511,
                    __t507,
                    __t515,
                    __t521,
                    __t511,
                    __t521,
                    __t525,
                ),
            }
        }
    }
    #[automatically_derived]
    impl ::routh::__private::DerivedFormulas for Gyrostat {
        const LAGRANGIAN: &'static str = "0.5·(ω₃·(ω₃·inertia[(2,2)] + ω₁·inertia[(0,2)] + ω₂·inertia[(1,2)]) + ω₁·(ω₃·inertia[(0,2)] + ω₁·inertia[(0,0)] + ω₂·inertia[(0,1)]) + ω₂·(ω₃·inertia[(1,2)] + ω₁·inertia[(0,1)] + ω₂·inertia[(1,1)])) + ω₃·(rotor[2] + γ₃·coupling[(2,2)] + γ₁·coupling[(2,0)] + γ₂·coupling[(2,1)]) + ω₁·(rotor[0] + γ₃·coupling[(0,2)] + γ₁·coupling[(0,0)] + γ₂·coupling[(0,1)]) + ω₂·(rotor[1] + γ₃·coupling[(1,2)] + γ₁·coupling[(1,0)] + γ₂·coupling[(1,1)]) - mass·g·(γ₃·com[2] + γ₁·com[0] + γ₂·com[1])";
        const AMENDED_POTENTIAL: &'static str = "mass·g·(γ₃·com[2] + γ₁·com[0] + γ₂·com[1]) + 0.5·(p_ψ - (γ₃·(rotor[2] + γ₃·coupling[(2,2)] + γ₁·coupling[(2,0)] + γ₂·coupling[(2,1)]) + γ₁·(rotor[0] + γ₃·coupling[(0,2)] + γ₁·coupling[(0,0)] + γ₂·coupling[(0,1)]) + γ₂·(rotor[1] + γ₃·coupling[(1,2)] + γ₁·coupling[(1,0)] + γ₂·coupling[(1,1)])))^2 / (γ₃·(γ₃·inertia[(2,2)] + γ₁·inertia[(0,2)] + γ₂·inertia[(1,2)]) + γ₁·(γ₃·inertia[(0,2)] + γ₁·inertia[(0,0)] + γ₂·inertia[(0,1)]) + γ₂·(γ₃·inertia[(1,2)] + γ₁·inertia[(0,1)] + γ₂·inertia[(1,1)]))";
        const PSI_DOT_AT_REST: &'static str = "(p_ψ - (γ₃·(rotor[2] + γ₃·coupling[(2,2)] + γ₁·coupling[(2,0)] + γ₂·coupling[(2,1)]) + γ₁·(rotor[0] + γ₃·coupling[(0,2)] + γ₁·coupling[(0,0)] + γ₂·coupling[(0,1)]) + γ₂·(rotor[1] + γ₃·coupling[(1,2)] + γ₁·coupling[(1,0)] + γ₂·coupling[(1,1)]))) / (γ₃·(γ₃·inertia[(2,2)] + γ₁·inertia[(0,2)] + γ₂·inertia[(1,2)]) + γ₁·(γ₃·inertia[(0,2)] + γ₁·inertia[(0,0)] + γ₂·inertia[(0,1)]) + γ₂·(γ₃·inertia[(1,2)] + γ₁·inertia[(0,1)] + γ₂·inertia[(1,1)]))";
    }
};
