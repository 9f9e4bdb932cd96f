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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            ::routh::__private::Vector3::new(__t95, __t103, __t107)
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
            let __t108: ::routh::__private::f64 = __v25 * __t76;
            let __t110: ::routh::__private::f64 = __v1 * __v19;
            let __t111: ::routh::__private::f64 = __v0 * __v16;
            let __t112: ::routh::__private::f64 = __t110 + __t111;
            let __t113: ::routh::__private::f64 = __v2 * __v22;
            let __t114: ::routh::__private::f64 = __t112 + __t113;
            let __t115: ::routh::__private::f64 = __t114 - __t108;
            let __t116: ::routh::__private::f64 = __v26 * __t76;
            let __t118: ::routh::__private::f64 = __v1 * __v20;
            let __t119: ::routh::__private::f64 = __v0 * __v17;
            let __t120: ::routh::__private::f64 = __t118 + __t119;
            let __t121: ::routh::__private::f64 = __v2 * __v23;
            let __t122: ::routh::__private::f64 = __t120 + __t121;
            let __t123: ::routh::__private::f64 = __t122 - __t116;
            let __t124: ::routh::__private::f64 = __v27 * __t76;
            let __t126: ::routh::__private::f64 = __v1 * __v21;
            let __t127: ::routh::__private::f64 = __v0 * __v18;
            let __t128: ::routh::__private::f64 = __t126 + __t127;
            let __t129: ::routh::__private::f64 = __v2 * __v24;
            let __t130: ::routh::__private::f64 = __t128 + __t129;
            let __t131: ::routh::__private::f64 = __t130 - __t124;
            ::routh::__private::Vector3::new(__t115, __t123, __t131)
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t132: ::routh::__private::f64 = __v0 * __t95;
            let __t133: ::routh::__private::f64 = __v1 * __t103;
            let __t134: ::routh::__private::f64 = __v2 * __t107;
            let __t135: ::routh::__private::f64 = __t132 + __t133;
            let __t136: ::routh::__private::f64 = __t134 + __t135;
            let __t138: ::routh::__private::f64 = __t136 - __t85;
            __t138
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t139: ::routh::__private::f64 = __v3 * __t95;
            let __t140: ::routh::__private::f64 = __v4 * __t103;
            let __t141: ::routh::__private::f64 = __v5 * __t107;
            let __t142: ::routh::__private::f64 = __t139 + __t140;
            let __t143: ::routh::__private::f64 = __t141 + __t142;
            __t143
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t139: ::routh::__private::f64 = __v3 * __t95;
            let __t140: ::routh::__private::f64 = __v4 * __t103;
            let __t141: ::routh::__private::f64 = __v5 * __t107;
            let __t142: ::routh::__private::f64 = __t139 + __t140;
            let __t143: ::routh::__private::f64 = __t141 + __t142;
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t166: ::routh::__private::f64 = __v6 - __t143;
            let __t168: ::routh::__private::f64 = __t166 / __t163;
            __t168
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t139: ::routh::__private::f64 = __v3 * __t95;
            let __t140: ::routh::__private::f64 = __v4 * __t103;
            let __t141: ::routh::__private::f64 = __v5 * __t107;
            let __t142: ::routh::__private::f64 = __t139 + __t140;
            let __t143: ::routh::__private::f64 = __t141 + __t142;
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t166: ::routh::__private::f64 = __v6 - __t143;
            let __t168: ::routh::__private::f64 = __t166 / __t163;
            let __t170: ::routh::__private::f64 = __t166 * __t168;
            let __t173: ::routh::__private::f64 = (-0.5f64) * __t170;
            let __t174: ::routh::__private::f64 = __t85 + __t173;
            __t174
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t139: ::routh::__private::f64 = __v3 * __t95;
            let __t140: ::routh::__private::f64 = __v4 * __t103;
            let __t141: ::routh::__private::f64 = __v5 * __t107;
            let __t142: ::routh::__private::f64 = __t139 + __t140;
            let __t143: ::routh::__private::f64 = __t141 + __t142;
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t166: ::routh::__private::f64 = __v6 - __t143;
            let __t168: ::routh::__private::f64 = __t166 / __t163;
            let __t377: ::routh::__private::f64 = __t148 * __t168;
            let __t378: ::routh::__private::f64 = __t95 + __t377;
            let __t379: ::routh::__private::f64 = __t153 * __t168;
            let __t380: ::routh::__private::f64 = __t103 + __t379;
            let __t381: ::routh::__private::f64 = __t158 * __t168;
            let __t382: ::routh::__private::f64 = __t107 + __t381;
            ::routh::__private::Vector3::new(__t378, __t380, __t382)
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t108: ::routh::__private::f64 = __v25 * __t76;
            let __t110: ::routh::__private::f64 = __v1 * __v19;
            let __t111: ::routh::__private::f64 = __v0 * __v16;
            let __t112: ::routh::__private::f64 = __t110 + __t111;
            let __t113: ::routh::__private::f64 = __v2 * __v22;
            let __t114: ::routh::__private::f64 = __t112 + __t113;
            let __t115: ::routh::__private::f64 = __t114 - __t108;
            let __t116: ::routh::__private::f64 = __v26 * __t76;
            let __t118: ::routh::__private::f64 = __v1 * __v20;
            let __t119: ::routh::__private::f64 = __v0 * __v17;
            let __t120: ::routh::__private::f64 = __t118 + __t119;
            let __t121: ::routh::__private::f64 = __v2 * __v23;
            let __t122: ::routh::__private::f64 = __t120 + __t121;
            let __t123: ::routh::__private::f64 = __t122 - __t116;
            let __t124: ::routh::__private::f64 = __v27 * __t76;
            let __t126: ::routh::__private::f64 = __v1 * __v21;
            let __t127: ::routh::__private::f64 = __v0 * __v18;
            let __t128: ::routh::__private::f64 = __t126 + __t127;
            let __t129: ::routh::__private::f64 = __v2 * __v24;
            let __t130: ::routh::__private::f64 = __t128 + __t129;
            let __t131: ::routh::__private::f64 = __t130 - __t124;
            let __t139: ::routh::__private::f64 = __v3 * __t95;
            let __t140: ::routh::__private::f64 = __v4 * __t103;
            let __t141: ::routh::__private::f64 = __v5 * __t107;
            let __t142: ::routh::__private::f64 = __t139 + __t140;
            let __t143: ::routh::__private::f64 = __t141 + __t142;
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t166: ::routh::__private::f64 = __v6 - __t143;
            let __t168: ::routh::__private::f64 = __t166 / __t163;
            let __t188: ::routh::__private::f64 = __v4 * __v19;
            let __t189: ::routh::__private::f64 = __v13 + __t32;
            let __t190: ::routh::__private::f64 = __t33 + __t189;
            let __t191: ::routh::__private::f64 = __t34 + __t190;
            let __t192: ::routh::__private::f64 = 2f64 * __t53;
            let __t193: ::routh::__private::f64 = __t191 + __t192;
            let __t194: ::routh::__private::f64 = __t54 + __t193;
            let __t195: ::routh::__private::f64 = __t55 + __t194;
            let __t196: ::routh::__private::f64 = __t188 + __t195;
            let __t197: ::routh::__private::f64 = __v5 * __v22;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t211: ::routh::__private::f64 = __v14 + __t37;
            let __t212: ::routh::__private::f64 = __t38 + __t211;
            let __t213: ::routh::__private::f64 = __t39 + __t212;
            let __t214: ::routh::__private::f64 = __t58 + __t213;
            let __t215: ::routh::__private::f64 = 2f64 * __t59;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t60 + __t216;
            let __t218: ::routh::__private::f64 = __v3 * __v17;
            let __t219: ::routh::__private::f64 = __t217 + __t218;
            let __t220: ::routh::__private::f64 = __v5 * __v23;
            let __t221: ::routh::__private::f64 = __t219 + __t220;
            let __t234: ::routh::__private::f64 = __v4 * __v21;
            let __t235: ::routh::__private::f64 = __v3 * __v18;
            let __t236: ::routh::__private::f64 = __t234 + __t235;
            let __t237: ::routh::__private::f64 = __v15 + __t42;
            let __t238: ::routh::__private::f64 = __t43 + __t237;
            let __t239: ::routh::__private::f64 = __t44 + __t238;
            let __t240: ::routh::__private::f64 = __t63 + __t239;
            let __t241: ::routh::__private::f64 = __t64 + __t240;
            let __t242: ::routh::__private::f64 = 2f64 * __t65;
            let __t243: ::routh::__private::f64 = __t241 + __t242;
            let __t244: ::routh::__private::f64 = __t236 + __t243;
            let __t371: ::routh::__private::f64 = __t168 * __t168;
            let __t383: ::routh::__private::f64 = __t168 * __t198;
            let __t384: ::routh::__private::f64 = __t115 + __t383;
            let __t385: ::routh::__private::f64 = __t148 * __t371;
            let __t387: ::routh::__private::f64 = __t384 + __t385;
            let __t388: ::routh::__private::f64 = __t168 * __t221;
            let __t389: ::routh::__private::f64 = __t123 + __t388;
            let __t390: ::routh::__private::f64 = __t153 * __t371;
            let __t392: ::routh::__private::f64 = __t389 + __t390;
            let __t393: ::routh::__private::f64 = __t168 * __t244;
            let __t394: ::routh::__private::f64 = __t131 + __t393;
            let __t395: ::routh::__private::f64 = __t158 * __t371;
            let __t397: ::routh::__private::f64 = __t394 + __t395;
            ::routh::__private::Vector3::new(__t387, __t392, __t397)
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t139: ::routh::__private::f64 = __v3 * __t95;
            let __t140: ::routh::__private::f64 = __v4 * __t103;
            let __t141: ::routh::__private::f64 = __v5 * __t107;
            let __t142: ::routh::__private::f64 = __t139 + __t140;
            let __t143: ::routh::__private::f64 = __t141 + __t142;
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t166: ::routh::__private::f64 = __v6 - __t143;
            let __t168: ::routh::__private::f64 = __t166 / __t163;
            let __t489: ::routh::__private::f64 = -__t168;
            __t489
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
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t167: ::routh::__private::f64 = 1.0f64 / __t163;
            let __t260: ::routh::__private::f64 = __t148 * __t167;
            let __t261: ::routh::__private::f64 = __t153 * __t167;
            let __t262: ::routh::__private::f64 = __t158 * __t167;
            let __t266: ::routh::__private::f64 = __t148 * __t260;
            let __t268: ::routh::__private::f64 = __v7 - __t266;
            let __t269: ::routh::__private::f64 = __t153 * __t260;
            let __t271: ::routh::__private::f64 = __v8 - __t269;
            let __t272: ::routh::__private::f64 = __t158 * __t260;
            let __t274: ::routh::__private::f64 = __v9 - __t272;
            let __t290: ::routh::__private::f64 = __t153 * __t261;
            let __t292: ::routh::__private::f64 = __v10 - __t290;
            let __t293: ::routh::__private::f64 = __t158 * __t261;
            let __t295: ::routh::__private::f64 = __v11 - __t293;
            let __t310: ::routh::__private::f64 = __t158 * __t262;
            let __t312: ::routh::__private::f64 = __v12 - __t310;
            ::routh::__private::Matrix3::new(
                __t268,
                __t271,
                __t274,
                __t271,
                __t292,
                __t295,
                __t274,
                __t295,
                __t312,
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t139: ::routh::__private::f64 = __v3 * __t95;
            let __t140: ::routh::__private::f64 = __v4 * __t103;
            let __t141: ::routh::__private::f64 = __v5 * __t107;
            let __t142: ::routh::__private::f64 = __t139 + __t140;
            let __t143: ::routh::__private::f64 = __t141 + __t142;
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t166: ::routh::__private::f64 = __v6 - __t143;
            let __t167: ::routh::__private::f64 = 1.0f64 / __t163;
            let __t168: ::routh::__private::f64 = __t166 * __t167;
            let __t188: ::routh::__private::f64 = __v4 * __v19;
            let __t189: ::routh::__private::f64 = __v13 + __t32;
            let __t190: ::routh::__private::f64 = __t33 + __t189;
            let __t191: ::routh::__private::f64 = __t34 + __t190;
            let __t192: ::routh::__private::f64 = 2f64 * __t53;
            let __t193: ::routh::__private::f64 = __t191 + __t192;
            let __t194: ::routh::__private::f64 = __t54 + __t193;
            let __t195: ::routh::__private::f64 = __t55 + __t194;
            let __t196: ::routh::__private::f64 = __t188 + __t195;
            let __t197: ::routh::__private::f64 = __v5 * __v22;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t211: ::routh::__private::f64 = __v14 + __t37;
            let __t212: ::routh::__private::f64 = __t38 + __t211;
            let __t213: ::routh::__private::f64 = __t39 + __t212;
            let __t214: ::routh::__private::f64 = __t58 + __t213;
            let __t215: ::routh::__private::f64 = 2f64 * __t59;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t60 + __t216;
            let __t218: ::routh::__private::f64 = __v3 * __v17;
            let __t219: ::routh::__private::f64 = __t217 + __t218;
            let __t220: ::routh::__private::f64 = __v5 * __v23;
            let __t221: ::routh::__private::f64 = __t219 + __t220;
            let __t234: ::routh::__private::f64 = __v4 * __v21;
            let __t235: ::routh::__private::f64 = __v3 * __v18;
            let __t236: ::routh::__private::f64 = __t234 + __t235;
            let __t237: ::routh::__private::f64 = __v15 + __t42;
            let __t238: ::routh::__private::f64 = __t43 + __t237;
            let __t239: ::routh::__private::f64 = __t44 + __t238;
            let __t240: ::routh::__private::f64 = __t63 + __t239;
            let __t241: ::routh::__private::f64 = __t64 + __t240;
            let __t242: ::routh::__private::f64 = 2f64 * __t65;
            let __t243: ::routh::__private::f64 = __t241 + __t242;
            let __t244: ::routh::__private::f64 = __t236 + __t243;
            let __t260: ::routh::__private::f64 = __t148 * __t167;
            let __t261: ::routh::__private::f64 = __t153 * __t167;
            let __t262: ::routh::__private::f64 = __t158 * __t167;
            let __t377: ::routh::__private::f64 = __t148 * __t168;
            let __t379: ::routh::__private::f64 = __t153 * __t168;
            let __t381: ::routh::__private::f64 = __t158 * __t168;
            let __t399: ::routh::__private::f64 = 2f64 * __t377;
            let __t400: ::routh::__private::f64 = __t198 + __t399;
            let __t401: ::routh::__private::f64 = 2f64 * __t379;
            let __t402: ::routh::__private::f64 = __t221 + __t401;
            let __t403: ::routh::__private::f64 = 2f64 * __t381;
            let __t404: ::routh::__private::f64 = __t244 + __t403;
            let __t408: ::routh::__private::f64 = __v7 * __t168;
            let __t409: ::routh::__private::f64 = __v16 + __t408;
            let __t410: ::routh::__private::f64 = __t260 * __t400;
            let __t412: ::routh::__private::f64 = __t409 - __t410;
            let __t413: ::routh::__private::f64 = __v8 * __t168;
            let __t414: ::routh::__private::f64 = __v17 + __t413;
            let __t415: ::routh::__private::f64 = __t260 * __t402;
            let __t417: ::routh::__private::f64 = __t414 - __t415;
            let __t418: ::routh::__private::f64 = __v9 * __t168;
            let __t419: ::routh::__private::f64 = __v18 + __t418;
            let __t420: ::routh::__private::f64 = __t260 * __t404;
            let __t422: ::routh::__private::f64 = __t419 - __t420;
            let __t423: ::routh::__private::f64 = __v19 + __t413;
            let __t424: ::routh::__private::f64 = __t261 * __t400;
            let __t426: ::routh::__private::f64 = __t423 - __t424;
            let __t427: ::routh::__private::f64 = __v10 * __t168;
            let __t428: ::routh::__private::f64 = __v20 + __t427;
            let __t429: ::routh::__private::f64 = __t261 * __t402;
            let __t431: ::routh::__private::f64 = __t428 - __t429;
            let __t432: ::routh::__private::f64 = __v11 * __t168;
            let __t433: ::routh::__private::f64 = __v21 + __t432;
            let __t434: ::routh::__private::f64 = __t261 * __t404;
            let __t436: ::routh::__private::f64 = __t433 - __t434;
            let __t437: ::routh::__private::f64 = __v22 + __t418;
            let __t438: ::routh::__private::f64 = __t262 * __t400;
            let __t440: ::routh::__private::f64 = __t437 - __t438;
            let __t441: ::routh::__private::f64 = __v23 + __t432;
            let __t442: ::routh::__private::f64 = __t262 * __t402;
            let __t444: ::routh::__private::f64 = __t441 - __t442;
            let __t445: ::routh::__private::f64 = __v12 * __t168;
            let __t446: ::routh::__private::f64 = __v24 + __t445;
            let __t447: ::routh::__private::f64 = __t262 * __t404;
            let __t449: ::routh::__private::f64 = __t446 - __t447;
            ::routh::__private::Matrix3::new(
                __t412,
                __t417,
                __t422,
                __t426,
                __t431,
                __t436,
                __t440,
                __t444,
                __t449,
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t139: ::routh::__private::f64 = __v3 * __t95;
            let __t140: ::routh::__private::f64 = __v4 * __t103;
            let __t141: ::routh::__private::f64 = __v5 * __t107;
            let __t142: ::routh::__private::f64 = __t139 + __t140;
            let __t143: ::routh::__private::f64 = __t141 + __t142;
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t166: ::routh::__private::f64 = __v6 - __t143;
            let __t167: ::routh::__private::f64 = 1.0f64 / __t163;
            let __t168: ::routh::__private::f64 = __t166 * __t167;
            let __t188: ::routh::__private::f64 = __v4 * __v19;
            let __t189: ::routh::__private::f64 = __v13 + __t32;
            let __t190: ::routh::__private::f64 = __t33 + __t189;
            let __t191: ::routh::__private::f64 = __t34 + __t190;
            let __t192: ::routh::__private::f64 = 2f64 * __t53;
            let __t193: ::routh::__private::f64 = __t191 + __t192;
            let __t194: ::routh::__private::f64 = __t54 + __t193;
            let __t195: ::routh::__private::f64 = __t55 + __t194;
            let __t196: ::routh::__private::f64 = __t188 + __t195;
            let __t197: ::routh::__private::f64 = __v5 * __v22;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t211: ::routh::__private::f64 = __v14 + __t37;
            let __t212: ::routh::__private::f64 = __t38 + __t211;
            let __t213: ::routh::__private::f64 = __t39 + __t212;
            let __t214: ::routh::__private::f64 = __t58 + __t213;
            let __t215: ::routh::__private::f64 = 2f64 * __t59;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t60 + __t216;
            let __t218: ::routh::__private::f64 = __v3 * __v17;
            let __t219: ::routh::__private::f64 = __t217 + __t218;
            let __t220: ::routh::__private::f64 = __v5 * __v23;
            let __t221: ::routh::__private::f64 = __t219 + __t220;
            let __t234: ::routh::__private::f64 = __v4 * __v21;
            let __t235: ::routh::__private::f64 = __v3 * __v18;
            let __t236: ::routh::__private::f64 = __t234 + __t235;
            let __t237: ::routh::__private::f64 = __v15 + __t42;
            let __t238: ::routh::__private::f64 = __t43 + __t237;
            let __t239: ::routh::__private::f64 = __t44 + __t238;
            let __t240: ::routh::__private::f64 = __t63 + __t239;
            let __t241: ::routh::__private::f64 = __t64 + __t240;
            let __t242: ::routh::__private::f64 = 2f64 * __t65;
            let __t243: ::routh::__private::f64 = __t241 + __t242;
            let __t244: ::routh::__private::f64 = __t236 + __t243;
            let __t335: ::routh::__private::f64 = __v17 + __v19;
            let __t342: ::routh::__private::f64 = __v18 + __v22;
            let __t357: ::routh::__private::f64 = __v21 + __v23;
            let __t371: ::routh::__private::f64 = __t168 * __t168;
            let __t377: ::routh::__private::f64 = __t148 * __t168;
            let __t379: ::routh::__private::f64 = __t153 * __t168;
            let __t381: ::routh::__private::f64 = __t158 * __t168;
            let __t399: ::routh::__private::f64 = 2f64 * __t377;
            let __t400: ::routh::__private::f64 = __t198 + __t399;
            let __t401: ::routh::__private::f64 = 2f64 * __t379;
            let __t402: ::routh::__private::f64 = __t221 + __t401;
            let __t403: ::routh::__private::f64 = 2f64 * __t381;
            let __t404: ::routh::__private::f64 = __t244 + __t403;
            let __t405: ::routh::__private::f64 = __t167 * __t400;
            let __t406: ::routh::__private::f64 = __t167 * __t402;
            let __t407: ::routh::__private::f64 = __t167 * __t404;
            let __t450: ::routh::__private::f64 = __v7 * __t371;
            let __t451: ::routh::__private::f64 = __v16 * __t168;
            let __t452: ::routh::__private::f64 = 2f64 * __t451;
            let __t453: ::routh::__private::f64 = __t450 + __t452;
            let __t454: ::routh::__private::f64 = __t400 * __t405;
            let __t456: ::routh::__private::f64 = __t453 - __t454;
            let __t457: ::routh::__private::f64 = __v8 * __t371;
            let __t458: ::routh::__private::f64 = __t168 * __t335;
            let __t459: ::routh::__private::f64 = __t457 + __t458;
            let __t460: ::routh::__private::f64 = __t402 * __t405;
            let __t462: ::routh::__private::f64 = __t459 - __t460;
            let __t463: ::routh::__private::f64 = __v9 * __t371;
            let __t464: ::routh::__private::f64 = __t168 * __t342;
            let __t465: ::routh::__private::f64 = __t463 + __t464;
            let __t466: ::routh::__private::f64 = __t404 * __t405;
            let __t468: ::routh::__private::f64 = __t465 - __t466;
            let __t469: ::routh::__private::f64 = __v10 * __t371;
            let __t470: ::routh::__private::f64 = __v20 * __t168;
            let __t471: ::routh::__private::f64 = 2f64 * __t470;
            let __t472: ::routh::__private::f64 = __t469 + __t471;
            let __t473: ::routh::__private::f64 = __t402 * __t406;
            let __t475: ::routh::__private::f64 = __t472 - __t473;
            let __t476: ::routh::__private::f64 = __v11 * __t371;
            let __t477: ::routh::__private::f64 = __t168 * __t357;
            let __t478: ::routh::__private::f64 = __t476 + __t477;
            let __t479: ::routh::__private::f64 = __t404 * __t406;
            let __t481: ::routh::__private::f64 = __t478 - __t479;
            let __t482: ::routh::__private::f64 = __v12 * __t371;
            let __t483: ::routh::__private::f64 = __v24 * __t168;
            let __t484: ::routh::__private::f64 = 2f64 * __t483;
            let __t485: ::routh::__private::f64 = __t482 + __t484;
            let __t486: ::routh::__private::f64 = __t404 * __t407;
            let __t488: ::routh::__private::f64 = __t485 - __t486;
            ::routh::__private::Matrix3::new(
                __t456,
                __t462,
                __t468,
                __t462,
                __t475,
                __t481,
                __t468,
                __t481,
                __t488,
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
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t490: ::routh::__private::f64 = __v3 * __t68;
            let __t491: ::routh::__private::f64 = __v4 * __t69;
            let __t492: ::routh::__private::f64 = __v5 * __t70;
            let __t493: ::routh::__private::f64 = __t490 + __t491;
            let __t494: ::routh::__private::f64 = __t492 + __t493;
            let __t496: ::routh::__private::f64 = __v6 - __t494;
            let __t497: ::routh::__private::f64 = __t496 / __t163;
            let __t499: ::routh::__private::f64 = __t496 * __t497;
            let __t501: ::routh::__private::f64 = (-0.5f64) * __t499;
            let __t502: ::routh::__private::f64 = __t501 - __t82;
            let __t701: ::routh::__private::f64 = -__t502;
            __t701
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
            let __t95: ::routh::__private::f64 = __t36 + __t68;
            let __t103: ::routh::__private::f64 = __t41 + __t69;
            let __t107: ::routh::__private::f64 = __t46 + __t70;
            let __t108: ::routh::__private::f64 = __v25 * __t76;
            let __t110: ::routh::__private::f64 = __v1 * __v19;
            let __t111: ::routh::__private::f64 = __v0 * __v16;
            let __t112: ::routh::__private::f64 = __t110 + __t111;
            let __t113: ::routh::__private::f64 = __v2 * __v22;
            let __t114: ::routh::__private::f64 = __t112 + __t113;
            let __t115: ::routh::__private::f64 = __t114 - __t108;
            let __t116: ::routh::__private::f64 = __v26 * __t76;
            let __t118: ::routh::__private::f64 = __v1 * __v20;
            let __t119: ::routh::__private::f64 = __v0 * __v17;
            let __t120: ::routh::__private::f64 = __t118 + __t119;
            let __t121: ::routh::__private::f64 = __v2 * __v23;
            let __t122: ::routh::__private::f64 = __t120 + __t121;
            let __t123: ::routh::__private::f64 = __t122 - __t116;
            let __t124: ::routh::__private::f64 = __v27 * __t76;
            let __t126: ::routh::__private::f64 = __v1 * __v21;
            let __t127: ::routh::__private::f64 = __v0 * __v18;
            let __t128: ::routh::__private::f64 = __t126 + __t127;
            let __t129: ::routh::__private::f64 = __v2 * __v24;
            let __t130: ::routh::__private::f64 = __t128 + __t129;
            let __t131: ::routh::__private::f64 = __t130 - __t124;
            let __t139: ::routh::__private::f64 = __v3 * __t95;
            let __t140: ::routh::__private::f64 = __v4 * __t103;
            let __t141: ::routh::__private::f64 = __v5 * __t107;
            let __t142: ::routh::__private::f64 = __t139 + __t140;
            let __t143: ::routh::__private::f64 = __t141 + __t142;
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t166: ::routh::__private::f64 = __v6 - __t143;
            let __t167: ::routh::__private::f64 = 1.0f64 / __t163;
            let __t168: ::routh::__private::f64 = __t166 * __t167;
            let __t170: ::routh::__private::f64 = __t166 * __t168;
            let __t173: ::routh::__private::f64 = (-0.5f64) * __t170;
            let __t174: ::routh::__private::f64 = __t85 + __t173;
            let __t188: ::routh::__private::f64 = __v4 * __v19;
            let __t189: ::routh::__private::f64 = __v13 + __t32;
            let __t190: ::routh::__private::f64 = __t33 + __t189;
            let __t191: ::routh::__private::f64 = __t34 + __t190;
            let __t192: ::routh::__private::f64 = 2f64 * __t53;
            let __t193: ::routh::__private::f64 = __t191 + __t192;
            let __t194: ::routh::__private::f64 = __t54 + __t193;
            let __t195: ::routh::__private::f64 = __t55 + __t194;
            let __t196: ::routh::__private::f64 = __t188 + __t195;
            let __t197: ::routh::__private::f64 = __v5 * __v22;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t211: ::routh::__private::f64 = __v14 + __t37;
            let __t212: ::routh::__private::f64 = __t38 + __t211;
            let __t213: ::routh::__private::f64 = __t39 + __t212;
            let __t214: ::routh::__private::f64 = __t58 + __t213;
            let __t215: ::routh::__private::f64 = 2f64 * __t59;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t60 + __t216;
            let __t218: ::routh::__private::f64 = __v3 * __v17;
            let __t219: ::routh::__private::f64 = __t217 + __t218;
            let __t220: ::routh::__private::f64 = __v5 * __v23;
            let __t221: ::routh::__private::f64 = __t219 + __t220;
            let __t234: ::routh::__private::f64 = __v4 * __v21;
            let __t235: ::routh::__private::f64 = __v3 * __v18;
            let __t236: ::routh::__private::f64 = __t234 + __t235;
            let __t237: ::routh::__private::f64 = __v15 + __t42;
            let __t238: ::routh::__private::f64 = __t43 + __t237;
            let __t239: ::routh::__private::f64 = __t44 + __t238;
            let __t240: ::routh::__private::f64 = __t63 + __t239;
            let __t241: ::routh::__private::f64 = __t64 + __t240;
            let __t242: ::routh::__private::f64 = 2f64 * __t65;
            let __t243: ::routh::__private::f64 = __t241 + __t242;
            let __t244: ::routh::__private::f64 = __t236 + __t243;
            let __t260: ::routh::__private::f64 = __t148 * __t167;
            let __t261: ::routh::__private::f64 = __t153 * __t167;
            let __t262: ::routh::__private::f64 = __t158 * __t167;
            let __t266: ::routh::__private::f64 = __t148 * __t260;
            let __t268: ::routh::__private::f64 = __v7 - __t266;
            let __t269: ::routh::__private::f64 = __t153 * __t260;
            let __t271: ::routh::__private::f64 = __v8 - __t269;
            let __t272: ::routh::__private::f64 = __t158 * __t260;
            let __t274: ::routh::__private::f64 = __v9 - __t272;
            let __t290: ::routh::__private::f64 = __t153 * __t261;
            let __t292: ::routh::__private::f64 = __v10 - __t290;
            let __t293: ::routh::__private::f64 = __t158 * __t261;
            let __t295: ::routh::__private::f64 = __v11 - __t293;
            let __t310: ::routh::__private::f64 = __t158 * __t262;
            let __t312: ::routh::__private::f64 = __v12 - __t310;
            let __t335: ::routh::__private::f64 = __v17 + __v19;
            let __t342: ::routh::__private::f64 = __v18 + __v22;
            let __t357: ::routh::__private::f64 = __v21 + __v23;
            let __t371: ::routh::__private::f64 = __t168 * __t168;
            let __t377: ::routh::__private::f64 = __t148 * __t168;
            let __t378: ::routh::__private::f64 = __t95 + __t377;
            let __t379: ::routh::__private::f64 = __t153 * __t168;
            let __t380: ::routh::__private::f64 = __t103 + __t379;
            let __t381: ::routh::__private::f64 = __t158 * __t168;
            let __t382: ::routh::__private::f64 = __t107 + __t381;
            let __t383: ::routh::__private::f64 = __t168 * __t198;
            let __t384: ::routh::__private::f64 = __t115 + __t383;
            let __t385: ::routh::__private::f64 = __t148 * __t371;
            let __t387: ::routh::__private::f64 = __t384 + __t385;
            let __t388: ::routh::__private::f64 = __t168 * __t221;
            let __t389: ::routh::__private::f64 = __t123 + __t388;
            let __t390: ::routh::__private::f64 = __t153 * __t371;
            let __t392: ::routh::__private::f64 = __t389 + __t390;
            let __t393: ::routh::__private::f64 = __t168 * __t244;
            let __t394: ::routh::__private::f64 = __t131 + __t393;
            let __t395: ::routh::__private::f64 = __t158 * __t371;
            let __t397: ::routh::__private::f64 = __t394 + __t395;
            let __t399: ::routh::__private::f64 = 2f64 * __t377;
            let __t400: ::routh::__private::f64 = __t198 + __t399;
            let __t401: ::routh::__private::f64 = 2f64 * __t379;
            let __t402: ::routh::__private::f64 = __t221 + __t401;
            let __t403: ::routh::__private::f64 = 2f64 * __t381;
            let __t404: ::routh::__private::f64 = __t244 + __t403;
            let __t405: ::routh::__private::f64 = __t167 * __t400;
            let __t406: ::routh::__private::f64 = __t167 * __t402;
            let __t407: ::routh::__private::f64 = __t167 * __t404;
            let __t408: ::routh::__private::f64 = __v7 * __t168;
            let __t409: ::routh::__private::f64 = __v16 + __t408;
            let __t410: ::routh::__private::f64 = __t260 * __t400;
            let __t412: ::routh::__private::f64 = __t409 - __t410;
            let __t413: ::routh::__private::f64 = __v8 * __t168;
            let __t414: ::routh::__private::f64 = __v17 + __t413;
            let __t415: ::routh::__private::f64 = __t260 * __t402;
            let __t417: ::routh::__private::f64 = __t414 - __t415;
            let __t418: ::routh::__private::f64 = __v9 * __t168;
            let __t419: ::routh::__private::f64 = __v18 + __t418;
            let __t420: ::routh::__private::f64 = __t260 * __t404;
            let __t422: ::routh::__private::f64 = __t419 - __t420;
            let __t423: ::routh::__private::f64 = __v19 + __t413;
            let __t424: ::routh::__private::f64 = __t261 * __t400;
            let __t426: ::routh::__private::f64 = __t423 - __t424;
            let __t427: ::routh::__private::f64 = __v10 * __t168;
            let __t428: ::routh::__private::f64 = __v20 + __t427;
            let __t429: ::routh::__private::f64 = __t261 * __t402;
            let __t431: ::routh::__private::f64 = __t428 - __t429;
            let __t432: ::routh::__private::f64 = __v11 * __t168;
            let __t433: ::routh::__private::f64 = __v21 + __t432;
            let __t434: ::routh::__private::f64 = __t261 * __t404;
            let __t436: ::routh::__private::f64 = __t433 - __t434;
            let __t437: ::routh::__private::f64 = __v22 + __t418;
            let __t438: ::routh::__private::f64 = __t262 * __t400;
            let __t440: ::routh::__private::f64 = __t437 - __t438;
            let __t441: ::routh::__private::f64 = __v23 + __t432;
            let __t442: ::routh::__private::f64 = __t262 * __t402;
            let __t444: ::routh::__private::f64 = __t441 - __t442;
            let __t445: ::routh::__private::f64 = __v12 * __t168;
            let __t446: ::routh::__private::f64 = __v24 + __t445;
            let __t447: ::routh::__private::f64 = __t262 * __t404;
            let __t449: ::routh::__private::f64 = __t446 - __t447;
            let __t450: ::routh::__private::f64 = __v7 * __t371;
            let __t451: ::routh::__private::f64 = __v16 * __t168;
            let __t452: ::routh::__private::f64 = 2f64 * __t451;
            let __t453: ::routh::__private::f64 = __t450 + __t452;
            let __t454: ::routh::__private::f64 = __t400 * __t405;
            let __t456: ::routh::__private::f64 = __t453 - __t454;
            let __t457: ::routh::__private::f64 = __v8 * __t371;
            let __t458: ::routh::__private::f64 = __t168 * __t335;
            let __t459: ::routh::__private::f64 = __t457 + __t458;
            let __t460: ::routh::__private::f64 = __t402 * __t405;
            let __t462: ::routh::__private::f64 = __t459 - __t460;
            let __t463: ::routh::__private::f64 = __v9 * __t371;
            let __t464: ::routh::__private::f64 = __t168 * __t342;
            let __t465: ::routh::__private::f64 = __t463 + __t464;
            let __t466: ::routh::__private::f64 = __t404 * __t405;
            let __t468: ::routh::__private::f64 = __t465 - __t466;
            let __t469: ::routh::__private::f64 = __v10 * __t371;
            let __t470: ::routh::__private::f64 = __v20 * __t168;
            let __t471: ::routh::__private::f64 = 2f64 * __t470;
            let __t472: ::routh::__private::f64 = __t469 + __t471;
            let __t473: ::routh::__private::f64 = __t402 * __t406;
            let __t475: ::routh::__private::f64 = __t472 - __t473;
            let __t476: ::routh::__private::f64 = __v11 * __t371;
            let __t477: ::routh::__private::f64 = __t168 * __t357;
            let __t478: ::routh::__private::f64 = __t476 + __t477;
            let __t479: ::routh::__private::f64 = __t404 * __t406;
            let __t481: ::routh::__private::f64 = __t478 - __t479;
            let __t482: ::routh::__private::f64 = __v12 * __t371;
            let __t483: ::routh::__private::f64 = __v24 * __t168;
            let __t484: ::routh::__private::f64 = 2f64 * __t483;
            let __t485: ::routh::__private::f64 = __t482 + __t484;
            let __t486: ::routh::__private::f64 = __t404 * __t407;
            let __t488: ::routh::__private::f64 = __t485 - __t486;
            let __t489: ::routh::__private::f64 = -__t168;
            ::routh::__private::RouthBundle {
                routhian: __t174,
                psi_dot: __t168,
                dr_domega: ::routh::__private::Vector3::new(__t378, __t380, __t382),
                dr_dgamma: ::routh::__private::Vector3::new(__t387, __t392, __t397),
                dr_dp: __t489,
                d2r_domega2: ::routh::__private::Matrix3::new(
                    __t268,
                    __t271,
                    __t274,
                    __t271,
                    __t292,
                    __t295,
                    __t274,
                    __t295,
                    __t312,
                ),
                d2r_domega_dgamma: ::routh::__private::Matrix3::new(
                    __t412,
                    __t417,
                    __t422,
                    __t426,
                    __t431,
                    __t436,
                    __t440,
                    __t444,
                    __t449,
                ),
                d2r_dgamma2: ::routh::__private::Matrix3::new(
                    __t456,
                    __t462,
                    __t468,
                    __t462,
                    __t475,
                    __t481,
                    __t468,
                    __t481,
                    __t488,
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
            let __t108: ::routh::__private::f64 = __v25 * __t76;
            let __t116: ::routh::__private::f64 = __v26 * __t76;
            let __t124: ::routh::__private::f64 = __v27 * __t76;
            let __t144: ::routh::__private::f64 = __v3 * __v7;
            let __t145: ::routh::__private::f64 = __v4 * __v8;
            let __t146: ::routh::__private::f64 = __v5 * __v9;
            let __t147: ::routh::__private::f64 = __t144 + __t145;
            let __t148: ::routh::__private::f64 = __t146 + __t147;
            let __t149: ::routh::__private::f64 = __v3 * __v8;
            let __t150: ::routh::__private::f64 = __v4 * __v10;
            let __t151: ::routh::__private::f64 = __v5 * __v11;
            let __t152: ::routh::__private::f64 = __t149 + __t150;
            let __t153: ::routh::__private::f64 = __t151 + __t152;
            let __t154: ::routh::__private::f64 = __v3 * __v9;
            let __t155: ::routh::__private::f64 = __v4 * __v11;
            let __t156: ::routh::__private::f64 = __v5 * __v12;
            let __t157: ::routh::__private::f64 = __t154 + __t155;
            let __t158: ::routh::__private::f64 = __t156 + __t157;
            let __t159: ::routh::__private::f64 = __v3 * __t148;
            let __t160: ::routh::__private::f64 = __v4 * __t153;
            let __t161: ::routh::__private::f64 = __v5 * __t158;
            let __t162: ::routh::__private::f64 = __t159 + __t160;
            let __t163: ::routh::__private::f64 = __t161 + __t162;
            let __t167: ::routh::__private::f64 = 1.0f64 / __t163;
            let __t188: ::routh::__private::f64 = __v4 * __v19;
            let __t192: ::routh::__private::f64 = 2f64 * __t53;
            let __t197: ::routh::__private::f64 = __v5 * __v22;
            let __t215: ::routh::__private::f64 = 2f64 * __t59;
            let __t218: ::routh::__private::f64 = __v3 * __v17;
            let __t220: ::routh::__private::f64 = __v5 * __v23;
            let __t234: ::routh::__private::f64 = __v4 * __v21;
            let __t235: ::routh::__private::f64 = __v3 * __v18;
            let __t236: ::routh::__private::f64 = __t234 + __t235;
            let __t242: ::routh::__private::f64 = 2f64 * __t65;
            let __t260: ::routh::__private::f64 = __t148 * __t167;
            let __t261: ::routh::__private::f64 = __t153 * __t167;
            let __t262: ::routh::__private::f64 = __t158 * __t167;
            let __t266: ::routh::__private::f64 = __t148 * __t260;
            let __t268: ::routh::__private::f64 = __v7 - __t266;
            let __t269: ::routh::__private::f64 = __t153 * __t260;
            let __t271: ::routh::__private::f64 = __v8 - __t269;
            let __t272: ::routh::__private::f64 = __t158 * __t260;
            let __t274: ::routh::__private::f64 = __v9 - __t272;
            let __t290: ::routh::__private::f64 = __t153 * __t261;
            let __t292: ::routh::__private::f64 = __v10 - __t290;
            let __t293: ::routh::__private::f64 = __t158 * __t261;
            let __t295: ::routh::__private::f64 = __v11 - __t293;
            let __t310: ::routh::__private::f64 = __t158 * __t262;
            let __t312: ::routh::__private::f64 = __v12 - __t310;
            let __t335: ::routh::__private::f64 = __v17 + __v19;
            let __t342: ::routh::__private::f64 = __v18 + __v22;
            let __t357: ::routh::__private::f64 = __v21 + __v23;
            let __t490: ::routh::__private::f64 = __v3 * __t68;
            let __t491: ::routh::__private::f64 = __v4 * __t69;
            let __t492: ::routh::__private::f64 = __v5 * __t70;
            let __t493: ::routh::__private::f64 = __t490 + __t491;
            let __t494: ::routh::__private::f64 = __t492 + __t493;
            let __t496: ::routh::__private::f64 = __v6 - __t494;
            let __t497: ::routh::__private::f64 = __t167 * __t496;
            let __t509: ::routh::__private::f64 = __v13 + __t192;
            let __t510: ::routh::__private::f64 = __t54 + __t509;
            let __t511: ::routh::__private::f64 = __t55 + __t510;
            let __t512: ::routh::__private::f64 = __t188 + __t511;
            let __t513: ::routh::__private::f64 = __t197 + __t512;
            let __t517: ::routh::__private::f64 = __v14 + __t58;
            let __t518: ::routh::__private::f64 = __t215 + __t517;
            let __t519: ::routh::__private::f64 = __t60 + __t518;
            let __t520: ::routh::__private::f64 = __t218 + __t519;
            let __t521: ::routh::__private::f64 = __t220 + __t520;
            let __t525: ::routh::__private::f64 = __v15 + __t63;
            let __t526: ::routh::__private::f64 = __t64 + __t525;
            let __t527: ::routh::__private::f64 = __t242 + __t526;
            let __t528: ::routh::__private::f64 = __t236 + __t527;
            let __t583: ::routh::__private::f64 = __t497 * __t497;
            let __t589: ::routh::__private::f64 = __t148 * __t497;
            let __t590: ::routh::__private::f64 = __t68 + __t589;
            let __t591: ::routh::__private::f64 = __t153 * __t497;
            let __t592: ::routh::__private::f64 = __t69 + __t591;
            let __t593: ::routh::__private::f64 = __t158 * __t497;
            let __t594: ::routh::__private::f64 = __t70 + __t593;
            let __t595: ::routh::__private::f64 = __t497 * __t513;
            let __t596: ::routh::__private::f64 = __t595 - __t108;
            let __t597: ::routh::__private::f64 = __t148 * __t583;
            let __t599: ::routh::__private::f64 = __t596 + __t597;
            let __t600: ::routh::__private::f64 = __t497 * __t521;
            let __t601: ::routh::__private::f64 = __t600 - __t116;
            let __t602: ::routh::__private::f64 = __t153 * __t583;
            let __t604: ::routh::__private::f64 = __t601 + __t602;
            let __t605: ::routh::__private::f64 = __t497 * __t528;
            let __t606: ::routh::__private::f64 = __t605 - __t124;
            let __t607: ::routh::__private::f64 = __t158 * __t583;
            let __t609: ::routh::__private::f64 = __t606 + __t607;
            let __t611: ::routh::__private::f64 = 2f64 * __t589;
            let __t612: ::routh::__private::f64 = __t513 + __t611;
            let __t613: ::routh::__private::f64 = 2f64 * __t591;
            let __t614: ::routh::__private::f64 = __t521 + __t613;
            let __t615: ::routh::__private::f64 = 2f64 * __t593;
            let __t616: ::routh::__private::f64 = __t528 + __t615;
            let __t617: ::routh::__private::f64 = __t167 * __t612;
            let __t618: ::routh::__private::f64 = __t167 * __t614;
            let __t619: ::routh::__private::f64 = __t167 * __t616;
            let __t620: ::routh::__private::f64 = __v7 * __t497;
            let __t621: ::routh::__private::f64 = __v16 + __t620;
            let __t622: ::routh::__private::f64 = __t260 * __t612;
            let __t624: ::routh::__private::f64 = __t621 - __t622;
            let __t625: ::routh::__private::f64 = __v8 * __t497;
            let __t626: ::routh::__private::f64 = __v17 + __t625;
            let __t627: ::routh::__private::f64 = __t260 * __t614;
            let __t629: ::routh::__private::f64 = __t626 - __t627;
            let __t630: ::routh::__private::f64 = __v9 * __t497;
            let __t631: ::routh::__private::f64 = __v18 + __t630;
            let __t632: ::routh::__private::f64 = __t260 * __t616;
            let __t634: ::routh::__private::f64 = __t631 - __t632;
            let __t635: ::routh::__private::f64 = __v19 + __t625;
            let __t636: ::routh::__private::f64 = __t261 * __t612;
            let __t638: ::routh::__private::f64 = __t635 - __t636;
            let __t639: ::routh::__private::f64 = __v10 * __t497;
            let __t640: ::routh::__private::f64 = __v20 + __t639;
            let __t641: ::routh::__private::f64 = __t261 * __t614;
            let __t643: ::routh::__private::f64 = __t640 - __t641;
            let __t644: ::routh::__private::f64 = __v11 * __t497;
            let __t645: ::routh::__private::f64 = __v21 + __t644;
            let __t646: ::routh::__private::f64 = __t261 * __t616;
            let __t648: ::routh::__private::f64 = __t645 - __t646;
            let __t649: ::routh::__private::f64 = __v22 + __t630;
            let __t650: ::routh::__private::f64 = __t262 * __t612;
            let __t652: ::routh::__private::f64 = __t649 - __t650;
            let __t653: ::routh::__private::f64 = __v23 + __t644;
            let __t654: ::routh::__private::f64 = __t262 * __t614;
            let __t656: ::routh::__private::f64 = __t653 - __t654;
            let __t657: ::routh::__private::f64 = __v12 * __t497;
            let __t658: ::routh::__private::f64 = __v24 + __t657;
            let __t659: ::routh::__private::f64 = __t262 * __t616;
            let __t661: ::routh::__private::f64 = __t658 - __t659;
            let __t662: ::routh::__private::f64 = __v7 * __t583;
            let __t663: ::routh::__private::f64 = __v16 * __t497;
            let __t664: ::routh::__private::f64 = 2f64 * __t663;
            let __t665: ::routh::__private::f64 = __t662 + __t664;
            let __t666: ::routh::__private::f64 = __t612 * __t617;
            let __t668: ::routh::__private::f64 = __t665 - __t666;
            let __t669: ::routh::__private::f64 = __v8 * __t583;
            let __t670: ::routh::__private::f64 = __t335 * __t497;
            let __t671: ::routh::__private::f64 = __t669 + __t670;
            let __t672: ::routh::__private::f64 = __t614 * __t617;
            let __t674: ::routh::__private::f64 = __t671 - __t672;
            let __t675: ::routh::__private::f64 = __v9 * __t583;
            let __t676: ::routh::__private::f64 = __t342 * __t497;
            let __t677: ::routh::__private::f64 = __t675 + __t676;
            let __t678: ::routh::__private::f64 = __t616 * __t617;
            let __t680: ::routh::__private::f64 = __t677 - __t678;
            let __t681: ::routh::__private::f64 = __v10 * __t583;
            let __t682: ::routh::__private::f64 = __v20 * __t497;
            let __t683: ::routh::__private::f64 = 2f64 * __t682;
            let __t684: ::routh::__private::f64 = __t681 + __t683;
            let __t685: ::routh::__private::f64 = __t614 * __t618;
            let __t687: ::routh::__private::f64 = __t684 - __t685;
            let __t688: ::routh::__private::f64 = __v11 * __t583;
            let __t689: ::routh::__private::f64 = __t357 * __t497;
            let __t690: ::routh::__private::f64 = __t688 + __t689;
            let __t691: ::routh::__private::f64 = __t616 * __t618;
            let __t693: ::routh::__private::f64 = __t690 - __t691;
            let __t694: ::routh::__private::f64 = __v12 * __t583;
            let __t695: ::routh::__private::f64 = __v24 * __t497;
            let __t696: ::routh::__private::f64 = 2f64 * __t695;
            let __t697: ::routh::__private::f64 = __t694 + __t696;
            let __t698: ::routh::__private::f64 = __t616 * __t619;
            let __t700: ::routh::__private::f64 = __t697 - __t698;
            let __t712: ::routh::__private::f64 = __v5 * __t624;
            let __t714: ::routh::__private::f64 = __v3 * __t634;
            let __t715: ::routh::__private::f64 = __t714 - __t712;
            let __t716: ::routh::__private::f64 = __v4 * __t624;
            let __t717: ::routh::__private::f64 = __v3 * __t629;
            let __t719: ::routh::__private::f64 = __t716 - __t717;
            let __t720: ::routh::__private::f64 = __v5 * __t643;
            let __t721: ::routh::__private::f64 = __v4 * __t648;
            let __t723: ::routh::__private::f64 = __t720 - __t721;
            let __t728: ::routh::__private::f64 = __v4 * __t638;
            let __t729: ::routh::__private::f64 = __v3 * __t643;
            let __t731: ::routh::__private::f64 = __t728 - __t729;
            let __t732: ::routh::__private::f64 = __v5 * __t656;
            let __t733: ::routh::__private::f64 = __v4 * __t661;
            let __t735: ::routh::__private::f64 = __t732 - __t733;
            let __t736: ::routh::__private::f64 = __v5 * __t652;
            let __t738: ::routh::__private::f64 = __v3 * __t661;
            let __t739: ::routh::__private::f64 = __t738 - __t736;
            let __t747: ::routh::__private::f64 = __t721 - __t720;
            let __t749: ::routh::__private::f64 = __t733 - __t732;
            let __t751: ::routh::__private::f64 = __t712 - __t714;
            let __t755: ::routh::__private::f64 = __t736 - __t738;
            let __t757: ::routh::__private::f64 = __t717 - __t716;
            let __t759: ::routh::__private::f64 = __t729 - __t728;
            let __t762: ::routh::__private::f64 = __t715 + __t747;
            let __t763: ::routh::__private::f64 = __t594 + __t762;
            let __t764: ::routh::__private::f64 = 0.5f64 * __t763;
            let __t765: ::routh::__private::f64 = __t719 + __t749;
            let __t766: ::routh::__private::f64 = __t765 - __t592;
            let __t767: ::routh::__private::f64 = 0.5f64 * __t766;
            let __t768: ::routh::__private::f64 = __t723 + __t751;
            let __t769: ::routh::__private::f64 = __t768 - __t594;
            let __t770: ::routh::__private::f64 = 0.5f64 * __t769;
            let __t771: ::routh::__private::f64 = __t731 + __t755;
            let __t772: ::routh::__private::f64 = __t590 + __t771;
            let __t773: ::routh::__private::f64 = 0.5f64 * __t772;
            let __t774: ::routh::__private::f64 = __t735 + __t757;
            let __t775: ::routh::__private::f64 = __t592 + __t774;
            let __t776: ::routh::__private::f64 = 0.5f64 * __t775;
            let __t777: ::routh::__private::f64 = __t739 + __t759;
            let __t778: ::routh::__private::f64 = __t777 - __t590;
            let __t779: ::routh::__private::f64 = 0.5f64 * __t778;
            let __t780: ::routh::__private::f64 = __v3 * __t599;
            let __t781: ::routh::__private::f64 = __v4 * __t604;
            let __t782: ::routh::__private::f64 = __v5 * __t609;
            let __t783: ::routh::__private::f64 = __t780 + __t781;
            let __t784: ::routh::__private::f64 = __t782 + __t783;
            let __t786: ::routh::__private::f64 = __t784 - __t668;
            let __t790: ::routh::__private::f64 = __t784 - __t687;
            let __t793: ::routh::__private::f64 = __t784 - __t700;
            let __t794: ::routh::__private::f64 = __v5 * __t674;
            let __t796: ::routh::__private::f64 = __v4 * __t680;
            let __t798: ::routh::__private::f64 = __t796 - __t794;
            let __t799: ::routh::__private::f64 = __v5 * __t790;
            let __t800: ::routh::__private::f64 = __v4 * __t693;
            let __t802: ::routh::__private::f64 = __t799 + __t800;
            let __t803: ::routh::__private::f64 = __v5 * __t693;
            let __t805: ::routh::__private::f64 = __v4 * __t793;
            let __t807: ::routh::__private::f64 = __t803 + __t805;
            let __t809: ::routh::__private::f64 = __v5 * __t786;
            let __t811: ::routh::__private::f64 = __v3 * __t680;
            let __t813: ::routh::__private::f64 = __t809 + __t811;
            let __t815: ::routh::__private::f64 = __v3 * __t693;
            let __t817: ::routh::__private::f64 = __t794 - __t815;
            let __t818: ::routh::__private::f64 = __v5 * __t680;
            let __t820: ::routh::__private::f64 = __v3 * __t793;
            let __t821: ::routh::__private::f64 = __t818 + __t820;
            let __t822: ::routh::__private::f64 = __v4 * __t786;
            let __t823: ::routh::__private::f64 = __v3 * __t674;
            let __t825: ::routh::__private::f64 = __t822 + __t823;
            let __t826: ::routh::__private::f64 = __v4 * __t674;
            let __t828: ::routh::__private::f64 = __v3 * __t790;
            let __t830: ::routh::__private::f64 = __t826 + __t828;
            let __t832: ::routh::__private::f64 = __t815 - __t796;
            let __t833: ::routh::__private::f64 = __v5 * __t802;
            let __t834: ::routh::__private::f64 = __v4 * __t807;
            let __t836: ::routh::__private::f64 = __t833 + __t834;
            let __t837: ::routh::__private::f64 = __v5 * __t798;
            let __t839: ::routh::__private::f64 = __v3 * __t807;
            let __t841: ::routh::__private::f64 = __t837 + __t839;
            let __t842: ::routh::__private::f64 = -__t841;
            let __t843: ::routh::__private::f64 = __v4 * __t798;
            let __t844: ::routh::__private::f64 = __v3 * __t802;
            let __t846: ::routh::__private::f64 = __t843 - __t844;
            let __t847: ::routh::__private::f64 = __v5 * __t817;
            let __t848: ::routh::__private::f64 = __v4 * __t821;
            let __t850: ::routh::__private::f64 = __t847 - __t848;
            let __t851: ::routh::__private::f64 = __v5 * __t813;
            let __t853: ::routh::__private::f64 = __v3 * __t821;
            let __t854: ::routh::__private::f64 = __t851 + __t853;
            let __t855: ::routh::__private::f64 = __v4 * __t813;
            let __t857: ::routh::__private::f64 = __v3 * __t817;
            let __t859: ::routh::__private::f64 = __t855 + __t857;
            let __t860: ::routh::__private::f64 = -__t859;
            let __t861: ::routh::__private::f64 = __v5 * __t830;
            let __t863: ::routh::__private::f64 = __v4 * __t832;
            let __t865: ::routh::__private::f64 = __t861 + __t863;
            let __t866: ::routh::__private::f64 = -__t865;
            let __t867: ::routh::__private::f64 = __v5 * __t825;
            let __t869: ::routh::__private::f64 = __v3 * __t832;
            let __t870: ::routh::__private::f64 = __t869 - __t867;
            let __t871: ::routh::__private::f64 = __v4 * __t825;
            let __t872: ::routh::__private::f64 = __v3 * __t830;
            let __t874: ::routh::__private::f64 = __t871 + __t872;
            ::routh::__private::GyroscopicSystem {
                a: ::routh::__private::Matrix3::new(
                    __t268,
                    __t271,
                    __t274,
                    __t271,
                    __t292,
                    __t295,
                    __t274,
                    __t295,
                    __t312,
                ),
                g: ::routh::__private::Matrix3::new(
                    0f64,
                    __t764,
                    __t767,
                    __t770,
                    0f64,
                    __t773,
                    __t776,
                    __t779,
                    0f64,
                ),
                c: ::routh::__private::Matrix3::new(
                    __t836,
                    __t842,
                    __t846,
                    __t850,
                    __t854,
                    __t860,
                    __t866,
                    __t870,
                    __t874,
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
