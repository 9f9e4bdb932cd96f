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
            let __t87: ::routh::__private::f64 = __t32 + __t36;
            let __t88: ::routh::__private::f64 = __t33 + __t87;
            let __t89: ::routh::__private::f64 = __t34 + __t88;
            let __t90: ::routh::__private::f64 = 0.5f64 * __t89;
            let __t91: ::routh::__private::f64 = __t68 + __t90;
            let __t92: ::routh::__private::f64 = __t38 + __t41;
            let __t93: ::routh::__private::f64 = __t37 + __t92;
            let __t94: ::routh::__private::f64 = __t39 + __t93;
            let __t95: ::routh::__private::f64 = 0.5f64 * __t94;
            let __t96: ::routh::__private::f64 = __t69 + __t95;
            let __t97: ::routh::__private::f64 = __t44 + __t46;
            let __t98: ::routh::__private::f64 = __t45 + __t97;
            let __t99: ::routh::__private::f64 = 0.5f64 * __t98;
            let __t100: ::routh::__private::f64 = __t70 + __t99;
            ::routh::__private::Vector3::new(__t91, __t96, __t100)
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
            let __t101: ::routh::__private::f64 = __v25 * __t76;
            let __t103: ::routh::__private::f64 = __v1 * __v19;
            let __t104: ::routh::__private::f64 = __v0 * __v16;
            let __t105: ::routh::__private::f64 = __t103 + __t104;
            let __t106: ::routh::__private::f64 = __v2 * __v22;
            let __t107: ::routh::__private::f64 = __t105 + __t106;
            let __t108: ::routh::__private::f64 = __t107 - __t101;
            let __t109: ::routh::__private::f64 = __v26 * __t76;
            let __t111: ::routh::__private::f64 = __v1 * __v20;
            let __t112: ::routh::__private::f64 = __v0 * __v17;
            let __t113: ::routh::__private::f64 = __t111 + __t112;
            let __t114: ::routh::__private::f64 = __v2 * __v23;
            let __t115: ::routh::__private::f64 = __t113 + __t114;
            let __t116: ::routh::__private::f64 = __t115 - __t109;
            let __t117: ::routh::__private::f64 = __v27 * __t76;
            let __t119: ::routh::__private::f64 = __v1 * __v21;
            let __t120: ::routh::__private::f64 = __v0 * __v18;
            let __t121: ::routh::__private::f64 = __t119 + __t120;
            let __t122: ::routh::__private::f64 = __v2 * __v24;
            let __t123: ::routh::__private::f64 = __t121 + __t122;
            let __t124: ::routh::__private::f64 = __t123 - __t117;
            ::routh::__private::Vector3::new(__t108, __t116, __t124)
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
            let __t87: ::routh::__private::f64 = __t32 + __t36;
            let __t88: ::routh::__private::f64 = __t33 + __t87;
            let __t89: ::routh::__private::f64 = __t34 + __t88;
            let __t90: ::routh::__private::f64 = 0.5f64 * __t89;
            let __t91: ::routh::__private::f64 = __t68 + __t90;
            let __t92: ::routh::__private::f64 = __t38 + __t41;
            let __t93: ::routh::__private::f64 = __t37 + __t92;
            let __t94: ::routh::__private::f64 = __t39 + __t93;
            let __t95: ::routh::__private::f64 = 0.5f64 * __t94;
            let __t96: ::routh::__private::f64 = __t69 + __t95;
            let __t97: ::routh::__private::f64 = __t44 + __t46;
            let __t98: ::routh::__private::f64 = __t45 + __t97;
            let __t99: ::routh::__private::f64 = 0.5f64 * __t98;
            let __t100: ::routh::__private::f64 = __t70 + __t99;
            let __t132: ::routh::__private::f64 = __v0 * __t91;
            let __t133: ::routh::__private::f64 = __v1 * __t96;
            let __t134: ::routh::__private::f64 = __v2 * __t100;
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
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t207: ::routh::__private::f64 = __v4 * __t41;
            let __t208: ::routh::__private::f64 = __v1 * __t183;
            let __t209: ::routh::__private::f64 = __t207 + __t208;
            let __t210: ::routh::__private::f64 = __v3 * __t36;
            let __t211: ::routh::__private::f64 = __v0 * __t191;
            let __t212: ::routh::__private::f64 = __t210 + __t211;
            let __t213: ::routh::__private::f64 = __t209 + __t212;
            let __t214: ::routh::__private::f64 = __v5 * __t46;
            let __t215: ::routh::__private::f64 = __v2 * __t200;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t213 + __t216;
            let __t218: ::routh::__private::f64 = 0.5f64 * __t217;
            let __t219: ::routh::__private::f64 = __t178 + __t218;
            __t219
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
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t207: ::routh::__private::f64 = __v4 * __t41;
            let __t208: ::routh::__private::f64 = __v1 * __t183;
            let __t209: ::routh::__private::f64 = __t207 + __t208;
            let __t210: ::routh::__private::f64 = __v3 * __t36;
            let __t211: ::routh::__private::f64 = __v0 * __t191;
            let __t212: ::routh::__private::f64 = __t210 + __t211;
            let __t213: ::routh::__private::f64 = __t209 + __t212;
            let __t214: ::routh::__private::f64 = __v5 * __t46;
            let __t215: ::routh::__private::f64 = __v2 * __t200;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t213 + __t216;
            let __t218: ::routh::__private::f64 = 0.5f64 * __t217;
            let __t219: ::routh::__private::f64 = __t178 + __t218;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t227: ::routh::__private::f64 = __v6 - __t219;
            let __t229: ::routh::__private::f64 = __t227 / __t224;
            __t229
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
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t207: ::routh::__private::f64 = __v4 * __t41;
            let __t208: ::routh::__private::f64 = __v1 * __t183;
            let __t209: ::routh::__private::f64 = __t207 + __t208;
            let __t210: ::routh::__private::f64 = __v3 * __t36;
            let __t211: ::routh::__private::f64 = __v0 * __t191;
            let __t212: ::routh::__private::f64 = __t210 + __t211;
            let __t213: ::routh::__private::f64 = __t209 + __t212;
            let __t214: ::routh::__private::f64 = __v5 * __t46;
            let __t215: ::routh::__private::f64 = __v2 * __t200;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t213 + __t216;
            let __t218: ::routh::__private::f64 = 0.5f64 * __t217;
            let __t219: ::routh::__private::f64 = __t178 + __t218;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t227: ::routh::__private::f64 = __v6 - __t219;
            let __t229: ::routh::__private::f64 = __t227 / __t224;
            let __t231: ::routh::__private::f64 = __t227 * __t229;
            let __t234: ::routh::__private::f64 = (-0.5f64) * __t231;
            let __t235: ::routh::__private::f64 = __t85 + __t234;
            __t235
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
            let __t87: ::routh::__private::f64 = __t32 + __t36;
            let __t88: ::routh::__private::f64 = __t33 + __t87;
            let __t89: ::routh::__private::f64 = __t34 + __t88;
            let __t90: ::routh::__private::f64 = 0.5f64 * __t89;
            let __t91: ::routh::__private::f64 = __t68 + __t90;
            let __t92: ::routh::__private::f64 = __t38 + __t41;
            let __t93: ::routh::__private::f64 = __t37 + __t92;
            let __t94: ::routh::__private::f64 = __t39 + __t93;
            let __t95: ::routh::__private::f64 = 0.5f64 * __t94;
            let __t96: ::routh::__private::f64 = __t69 + __t95;
            let __t97: ::routh::__private::f64 = __t44 + __t46;
            let __t98: ::routh::__private::f64 = __t45 + __t97;
            let __t99: ::routh::__private::f64 = 0.5f64 * __t98;
            let __t100: ::routh::__private::f64 = __t70 + __t99;
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t207: ::routh::__private::f64 = __v4 * __t41;
            let __t208: ::routh::__private::f64 = __v1 * __t183;
            let __t209: ::routh::__private::f64 = __t207 + __t208;
            let __t210: ::routh::__private::f64 = __v3 * __t36;
            let __t211: ::routh::__private::f64 = __v0 * __t191;
            let __t212: ::routh::__private::f64 = __t210 + __t211;
            let __t213: ::routh::__private::f64 = __t209 + __t212;
            let __t214: ::routh::__private::f64 = __v5 * __t46;
            let __t215: ::routh::__private::f64 = __v2 * __t200;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t213 + __t216;
            let __t218: ::routh::__private::f64 = 0.5f64 * __t217;
            let __t219: ::routh::__private::f64 = __t178 + __t218;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t227: ::routh::__private::f64 = __v6 - __t219;
            let __t229: ::routh::__private::f64 = __t227 / __t224;
            let __t243: ::routh::__private::f64 = __t188 + __t191;
            let __t244: ::routh::__private::f64 = __t187 + __t243;
            let __t245: ::routh::__private::f64 = __t190 + __t244;
            let __t250: ::routh::__private::f64 = __t179 + __t183;
            let __t251: ::routh::__private::f64 = __t180 + __t250;
            let __t252: ::routh::__private::f64 = __t182 + __t251;
            let __t257: ::routh::__private::f64 = __t199 + __t200;
            let __t258: ::routh::__private::f64 = __t198 + __t257;
            let __t458: ::routh::__private::f64 = __t229 * __t245;
            let __t459: ::routh::__private::f64 = 0.5f64 * __t458;
            let __t460: ::routh::__private::f64 = __t91 + __t459;
            let __t461: ::routh::__private::f64 = __t229 * __t252;
            let __t462: ::routh::__private::f64 = 0.5f64 * __t461;
            let __t463: ::routh::__private::f64 = __t96 + __t462;
            let __t464: ::routh::__private::f64 = __t229 * __t258;
            let __t465: ::routh::__private::f64 = 0.5f64 * __t464;
            let __t466: ::routh::__private::f64 = __t100 + __t465;
            ::routh::__private::Vector3::new(__t460, __t463, __t466)
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
            let __t87: ::routh::__private::f64 = __t32 + __t36;
            let __t88: ::routh::__private::f64 = __t33 + __t87;
            let __t89: ::routh::__private::f64 = __t34 + __t88;
            let __t90: ::routh::__private::f64 = 0.5f64 * __t89;
            let __t92: ::routh::__private::f64 = __t38 + __t41;
            let __t93: ::routh::__private::f64 = __t37 + __t92;
            let __t94: ::routh::__private::f64 = __t39 + __t93;
            let __t95: ::routh::__private::f64 = 0.5f64 * __t94;
            let __t97: ::routh::__private::f64 = __t44 + __t46;
            let __t98: ::routh::__private::f64 = __t45 + __t97;
            let __t99: ::routh::__private::f64 = 0.5f64 * __t98;
            let __t101: ::routh::__private::f64 = __v25 * __t76;
            let __t103: ::routh::__private::f64 = __v1 * __v19;
            let __t104: ::routh::__private::f64 = __v0 * __v16;
            let __t105: ::routh::__private::f64 = __t103 + __t104;
            let __t106: ::routh::__private::f64 = __v2 * __v22;
            let __t107: ::routh::__private::f64 = __t105 + __t106;
            let __t108: ::routh::__private::f64 = __t107 - __t101;
            let __t109: ::routh::__private::f64 = __v26 * __t76;
            let __t111: ::routh::__private::f64 = __v1 * __v20;
            let __t112: ::routh::__private::f64 = __v0 * __v17;
            let __t113: ::routh::__private::f64 = __t111 + __t112;
            let __t114: ::routh::__private::f64 = __v2 * __v23;
            let __t115: ::routh::__private::f64 = __t113 + __t114;
            let __t116: ::routh::__private::f64 = __t115 - __t109;
            let __t117: ::routh::__private::f64 = __v27 * __t76;
            let __t119: ::routh::__private::f64 = __v1 * __v21;
            let __t120: ::routh::__private::f64 = __v0 * __v18;
            let __t121: ::routh::__private::f64 = __t119 + __t120;
            let __t122: ::routh::__private::f64 = __v2 * __v24;
            let __t123: ::routh::__private::f64 = __t121 + __t122;
            let __t124: ::routh::__private::f64 = __t123 - __t117;
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t207: ::routh::__private::f64 = __v4 * __t41;
            let __t208: ::routh::__private::f64 = __v1 * __t183;
            let __t209: ::routh::__private::f64 = __t207 + __t208;
            let __t210: ::routh::__private::f64 = __v3 * __t36;
            let __t211: ::routh::__private::f64 = __v0 * __t191;
            let __t212: ::routh::__private::f64 = __t210 + __t211;
            let __t213: ::routh::__private::f64 = __t209 + __t212;
            let __t214: ::routh::__private::f64 = __v5 * __t46;
            let __t215: ::routh::__private::f64 = __v2 * __t200;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t213 + __t216;
            let __t218: ::routh::__private::f64 = 0.5f64 * __t217;
            let __t219: ::routh::__private::f64 = __t178 + __t218;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t227: ::routh::__private::f64 = __v6 - __t219;
            let __t229: ::routh::__private::f64 = __t227 / __t224;
            let __t243: ::routh::__private::f64 = __t188 + __t191;
            let __t244: ::routh::__private::f64 = __t187 + __t243;
            let __t245: ::routh::__private::f64 = __t190 + __t244;
            let __t250: ::routh::__private::f64 = __t179 + __t183;
            let __t251: ::routh::__private::f64 = __t180 + __t250;
            let __t252: ::routh::__private::f64 = __t182 + __t251;
            let __t257: ::routh::__private::f64 = __t199 + __t200;
            let __t258: ::routh::__private::f64 = __t198 + __t257;
            let __t263: ::routh::__private::f64 = __v5 * __v22;
            let __t264: ::routh::__private::f64 = __t53 + __t68;
            let __t265: ::routh::__private::f64 = __v4 * __v19;
            let __t266: ::routh::__private::f64 = __t264 + __t265;
            let __t267: ::routh::__private::f64 = __t263 + __t266;
            let __t268: ::routh::__private::f64 = __t90 + __t267;
            let __t274: ::routh::__private::f64 = __v5 * __v23;
            let __t275: ::routh::__private::f64 = __v3 * __v17;
            let __t276: ::routh::__private::f64 = __t59 + __t69;
            let __t277: ::routh::__private::f64 = __t275 + __t276;
            let __t278: ::routh::__private::f64 = __t274 + __t277;
            let __t279: ::routh::__private::f64 = __t95 + __t278;
            let __t285: ::routh::__private::f64 = __t65 + __t70;
            let __t286: ::routh::__private::f64 = __v3 * __v18;
            let __t287: ::routh::__private::f64 = __v4 * __v21;
            let __t288: ::routh::__private::f64 = __t286 + __t287;
            let __t289: ::routh::__private::f64 = __t285 + __t288;
            let __t290: ::routh::__private::f64 = __t99 + __t289;
            let __t452: ::routh::__private::f64 = __t229 * __t229;
            let __t467: ::routh::__private::f64 = __t229 * __t268;
            let __t468: ::routh::__private::f64 = __t108 + __t467;
            let __t469: ::routh::__private::f64 = __t245 * __t452;
            let __t470: ::routh::__private::f64 = 0.5f64 * __t469;
            let __t471: ::routh::__private::f64 = __t468 + __t470;
            let __t472: ::routh::__private::f64 = __t229 * __t279;
            let __t473: ::routh::__private::f64 = __t116 + __t472;
            let __t474: ::routh::__private::f64 = __t252 * __t452;
            let __t475: ::routh::__private::f64 = 0.5f64 * __t474;
            let __t476: ::routh::__private::f64 = __t473 + __t475;
            let __t477: ::routh::__private::f64 = __t229 * __t290;
            let __t478: ::routh::__private::f64 = __t124 + __t477;
            let __t479: ::routh::__private::f64 = __t258 * __t452;
            let __t480: ::routh::__private::f64 = 0.5f64 * __t479;
            let __t481: ::routh::__private::f64 = __t478 + __t480;
            ::routh::__private::Vector3::new(__t471, __t476, __t481)
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
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t207: ::routh::__private::f64 = __v4 * __t41;
            let __t208: ::routh::__private::f64 = __v1 * __t183;
            let __t209: ::routh::__private::f64 = __t207 + __t208;
            let __t210: ::routh::__private::f64 = __v3 * __t36;
            let __t211: ::routh::__private::f64 = __v0 * __t191;
            let __t212: ::routh::__private::f64 = __t210 + __t211;
            let __t213: ::routh::__private::f64 = __t209 + __t212;
            let __t214: ::routh::__private::f64 = __v5 * __t46;
            let __t215: ::routh::__private::f64 = __v2 * __t200;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t213 + __t216;
            let __t218: ::routh::__private::f64 = 0.5f64 * __t217;
            let __t219: ::routh::__private::f64 = __t178 + __t218;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t227: ::routh::__private::f64 = __v6 - __t219;
            let __t229: ::routh::__private::f64 = __t227 / __t224;
            let __t594: ::routh::__private::f64 = -__t229;
            __t594
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
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t228: ::routh::__private::f64 = 1.0f64 / __t224;
            let __t243: ::routh::__private::f64 = __t188 + __t191;
            let __t244: ::routh::__private::f64 = __t187 + __t243;
            let __t245: ::routh::__private::f64 = __t190 + __t244;
            let __t250: ::routh::__private::f64 = __t179 + __t183;
            let __t251: ::routh::__private::f64 = __t180 + __t250;
            let __t252: ::routh::__private::f64 = __t182 + __t251;
            let __t257: ::routh::__private::f64 = __t199 + __t200;
            let __t258: ::routh::__private::f64 = __t198 + __t257;
            let __t303: ::routh::__private::f64 = __t228 * __t245;
            let __t305: ::routh::__private::f64 = __t228 * __t252;
            let __t307: ::routh::__private::f64 = __t228 * __t258;
            let __t312: ::routh::__private::f64 = __t245 * __t303;
            let __t317: ::routh::__private::f64 = (-0.25f64) * __t312;
            let __t318: ::routh::__private::f64 = __v7 + __t317;
            let __t319: ::routh::__private::f64 = __t252 * __t303;
            let __t322: ::routh::__private::f64 = (-0.25f64) * __t319;
            let __t323: ::routh::__private::f64 = __v8 + __t322;
            let __t324: ::routh::__private::f64 = __t258 * __t303;
            let __t327: ::routh::__private::f64 = (-0.25f64) * __t324;
            let __t328: ::routh::__private::f64 = __v9 + __t327;
            let __t350: ::routh::__private::f64 = __t252 * __t305;
            let __t353: ::routh::__private::f64 = (-0.25f64) * __t350;
            let __t354: ::routh::__private::f64 = __v10 + __t353;
            let __t355: ::routh::__private::f64 = __t258 * __t305;
            let __t358: ::routh::__private::f64 = (-0.25f64) * __t355;
            let __t359: ::routh::__private::f64 = __v11 + __t358;
            let __t379: ::routh::__private::f64 = __t258 * __t307;
            let __t382: ::routh::__private::f64 = (-0.25f64) * __t379;
            let __t383: ::routh::__private::f64 = __v12 + __t382;
            ::routh::__private::Matrix3::new(
                __t318,
                __t323,
                __t328,
                __t323,
                __t354,
                __t359,
                __t328,
                __t359,
                __t383,
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
            let __t87: ::routh::__private::f64 = __t32 + __t36;
            let __t88: ::routh::__private::f64 = __t33 + __t87;
            let __t89: ::routh::__private::f64 = __t34 + __t88;
            let __t90: ::routh::__private::f64 = 0.5f64 * __t89;
            let __t92: ::routh::__private::f64 = __t38 + __t41;
            let __t93: ::routh::__private::f64 = __t37 + __t92;
            let __t94: ::routh::__private::f64 = __t39 + __t93;
            let __t95: ::routh::__private::f64 = 0.5f64 * __t94;
            let __t97: ::routh::__private::f64 = __t44 + __t46;
            let __t98: ::routh::__private::f64 = __t45 + __t97;
            let __t99: ::routh::__private::f64 = 0.5f64 * __t98;
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t207: ::routh::__private::f64 = __v4 * __t41;
            let __t208: ::routh::__private::f64 = __v1 * __t183;
            let __t209: ::routh::__private::f64 = __t207 + __t208;
            let __t210: ::routh::__private::f64 = __v3 * __t36;
            let __t211: ::routh::__private::f64 = __v0 * __t191;
            let __t212: ::routh::__private::f64 = __t210 + __t211;
            let __t213: ::routh::__private::f64 = __t209 + __t212;
            let __t214: ::routh::__private::f64 = __v5 * __t46;
            let __t215: ::routh::__private::f64 = __v2 * __t200;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t213 + __t216;
            let __t218: ::routh::__private::f64 = 0.5f64 * __t217;
            let __t219: ::routh::__private::f64 = __t178 + __t218;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t227: ::routh::__private::f64 = __v6 - __t219;
            let __t228: ::routh::__private::f64 = 1.0f64 / __t224;
            let __t229: ::routh::__private::f64 = __t227 * __t228;
            let __t243: ::routh::__private::f64 = __t188 + __t191;
            let __t244: ::routh::__private::f64 = __t187 + __t243;
            let __t245: ::routh::__private::f64 = __t190 + __t244;
            let __t250: ::routh::__private::f64 = __t179 + __t183;
            let __t251: ::routh::__private::f64 = __t180 + __t250;
            let __t252: ::routh::__private::f64 = __t182 + __t251;
            let __t257: ::routh::__private::f64 = __t199 + __t200;
            let __t258: ::routh::__private::f64 = __t198 + __t257;
            let __t263: ::routh::__private::f64 = __v5 * __v22;
            let __t264: ::routh::__private::f64 = __t53 + __t68;
            let __t265: ::routh::__private::f64 = __v4 * __v19;
            let __t266: ::routh::__private::f64 = __t264 + __t265;
            let __t267: ::routh::__private::f64 = __t263 + __t266;
            let __t268: ::routh::__private::f64 = __t90 + __t267;
            let __t274: ::routh::__private::f64 = __v5 * __v23;
            let __t275: ::routh::__private::f64 = __v3 * __v17;
            let __t276: ::routh::__private::f64 = __t59 + __t69;
            let __t277: ::routh::__private::f64 = __t275 + __t276;
            let __t278: ::routh::__private::f64 = __t274 + __t277;
            let __t279: ::routh::__private::f64 = __t95 + __t278;
            let __t285: ::routh::__private::f64 = __t65 + __t70;
            let __t286: ::routh::__private::f64 = __v3 * __v18;
            let __t287: ::routh::__private::f64 = __v4 * __v21;
            let __t288: ::routh::__private::f64 = __t286 + __t287;
            let __t289: ::routh::__private::f64 = __t285 + __t288;
            let __t290: ::routh::__private::f64 = __t99 + __t289;
            let __t303: ::routh::__private::f64 = __t228 * __t245;
            let __t305: ::routh::__private::f64 = __t228 * __t252;
            let __t307: ::routh::__private::f64 = __t228 * __t258;
            let __t458: ::routh::__private::f64 = __t229 * __t245;
            let __t461: ::routh::__private::f64 = __t229 * __t252;
            let __t464: ::routh::__private::f64 = __t229 * __t258;
            let __t484: ::routh::__private::f64 = __t268 + __t458;
            let __t486: ::routh::__private::f64 = __t279 + __t461;
            let __t488: ::routh::__private::f64 = __t290 + __t464;
            let __t492: ::routh::__private::f64 = __v7 * __t229;
            let __t494: ::routh::__private::f64 = __v16 + __t492;
            let __t495: ::routh::__private::f64 = __t303 * __t484;
            let __t497: ::routh::__private::f64 = (-0.5f64) * __t495;
            let __t498: ::routh::__private::f64 = __t494 + __t497;
            let __t499: ::routh::__private::f64 = __v8 * __t229;
            let __t501: ::routh::__private::f64 = __v17 + __t499;
            let __t502: ::routh::__private::f64 = __t303 * __t486;
            let __t504: ::routh::__private::f64 = (-0.5f64) * __t502;
            let __t505: ::routh::__private::f64 = __t501 + __t504;
            let __t506: ::routh::__private::f64 = __v9 * __t229;
            let __t508: ::routh::__private::f64 = __v18 + __t506;
            let __t509: ::routh::__private::f64 = __t303 * __t488;
            let __t511: ::routh::__private::f64 = (-0.5f64) * __t509;
            let __t512: ::routh::__private::f64 = __t508 + __t511;
            let __t513: ::routh::__private::f64 = __v19 + __t499;
            let __t514: ::routh::__private::f64 = __t305 * __t484;
            let __t516: ::routh::__private::f64 = (-0.5f64) * __t514;
            let __t517: ::routh::__private::f64 = __t513 + __t516;
            let __t518: ::routh::__private::f64 = __v10 * __t229;
            let __t520: ::routh::__private::f64 = __v20 + __t518;
            let __t521: ::routh::__private::f64 = __t305 * __t486;
            let __t523: ::routh::__private::f64 = (-0.5f64) * __t521;
            let __t524: ::routh::__private::f64 = __t520 + __t523;
            let __t525: ::routh::__private::f64 = __v11 * __t229;
            let __t527: ::routh::__private::f64 = __v21 + __t525;
            let __t528: ::routh::__private::f64 = __t305 * __t488;
            let __t530: ::routh::__private::f64 = (-0.5f64) * __t528;
            let __t531: ::routh::__private::f64 = __t527 + __t530;
            let __t532: ::routh::__private::f64 = __v22 + __t506;
            let __t533: ::routh::__private::f64 = __t307 * __t484;
            let __t535: ::routh::__private::f64 = (-0.5f64) * __t533;
            let __t536: ::routh::__private::f64 = __t532 + __t535;
            let __t537: ::routh::__private::f64 = __v23 + __t525;
            let __t538: ::routh::__private::f64 = __t307 * __t486;
            let __t540: ::routh::__private::f64 = (-0.5f64) * __t538;
            let __t541: ::routh::__private::f64 = __t537 + __t540;
            let __t542: ::routh::__private::f64 = __v12 * __t229;
            let __t544: ::routh::__private::f64 = __v24 + __t542;
            let __t545: ::routh::__private::f64 = __t307 * __t488;
            let __t547: ::routh::__private::f64 = (-0.5f64) * __t545;
            let __t548: ::routh::__private::f64 = __t544 + __t547;
            ::routh::__private::Matrix3::new(
                __t498,
                __t505,
                __t512,
                __t517,
                __t524,
                __t531,
                __t536,
                __t541,
                __t548,
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
            let __t87: ::routh::__private::f64 = __t32 + __t36;
            let __t88: ::routh::__private::f64 = __t33 + __t87;
            let __t89: ::routh::__private::f64 = __t34 + __t88;
            let __t90: ::routh::__private::f64 = 0.5f64 * __t89;
            let __t92: ::routh::__private::f64 = __t38 + __t41;
            let __t93: ::routh::__private::f64 = __t37 + __t92;
            let __t94: ::routh::__private::f64 = __t39 + __t93;
            let __t95: ::routh::__private::f64 = 0.5f64 * __t94;
            let __t97: ::routh::__private::f64 = __t44 + __t46;
            let __t98: ::routh::__private::f64 = __t45 + __t97;
            let __t99: ::routh::__private::f64 = 0.5f64 * __t98;
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t207: ::routh::__private::f64 = __v4 * __t41;
            let __t208: ::routh::__private::f64 = __v1 * __t183;
            let __t209: ::routh::__private::f64 = __t207 + __t208;
            let __t210: ::routh::__private::f64 = __v3 * __t36;
            let __t211: ::routh::__private::f64 = __v0 * __t191;
            let __t212: ::routh::__private::f64 = __t210 + __t211;
            let __t213: ::routh::__private::f64 = __t209 + __t212;
            let __t214: ::routh::__private::f64 = __v5 * __t46;
            let __t215: ::routh::__private::f64 = __v2 * __t200;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t213 + __t216;
            let __t218: ::routh::__private::f64 = 0.5f64 * __t217;
            let __t219: ::routh::__private::f64 = __t178 + __t218;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t227: ::routh::__private::f64 = __v6 - __t219;
            let __t228: ::routh::__private::f64 = 1.0f64 / __t224;
            let __t229: ::routh::__private::f64 = __t227 * __t228;
            let __t243: ::routh::__private::f64 = __t188 + __t191;
            let __t244: ::routh::__private::f64 = __t187 + __t243;
            let __t245: ::routh::__private::f64 = __t190 + __t244;
            let __t250: ::routh::__private::f64 = __t179 + __t183;
            let __t251: ::routh::__private::f64 = __t180 + __t250;
            let __t252: ::routh::__private::f64 = __t182 + __t251;
            let __t257: ::routh::__private::f64 = __t199 + __t200;
            let __t258: ::routh::__private::f64 = __t198 + __t257;
            let __t263: ::routh::__private::f64 = __v5 * __v22;
            let __t264: ::routh::__private::f64 = __t53 + __t68;
            let __t265: ::routh::__private::f64 = __v4 * __v19;
            let __t266: ::routh::__private::f64 = __t264 + __t265;
            let __t267: ::routh::__private::f64 = __t263 + __t266;
            let __t268: ::routh::__private::f64 = __t90 + __t267;
            let __t274: ::routh::__private::f64 = __v5 * __v23;
            let __t275: ::routh::__private::f64 = __v3 * __v17;
            let __t276: ::routh::__private::f64 = __t59 + __t69;
            let __t277: ::routh::__private::f64 = __t275 + __t276;
            let __t278: ::routh::__private::f64 = __t274 + __t277;
            let __t279: ::routh::__private::f64 = __t95 + __t278;
            let __t285: ::routh::__private::f64 = __t65 + __t70;
            let __t286: ::routh::__private::f64 = __v3 * __v18;
            let __t287: ::routh::__private::f64 = __v4 * __v21;
            let __t288: ::routh::__private::f64 = __t286 + __t287;
            let __t289: ::routh::__private::f64 = __t285 + __t288;
            let __t290: ::routh::__private::f64 = __t99 + __t289;
            let __t412: ::routh::__private::f64 = __v17 + __v19;
            let __t420: ::routh::__private::f64 = __v18 + __v22;
            let __t437: ::routh::__private::f64 = __v21 + __v23;
            let __t452: ::routh::__private::f64 = __t229 * __t229;
            let __t458: ::routh::__private::f64 = __t229 * __t245;
            let __t461: ::routh::__private::f64 = __t229 * __t252;
            let __t464: ::routh::__private::f64 = __t229 * __t258;
            let __t484: ::routh::__private::f64 = __t268 + __t458;
            let __t486: ::routh::__private::f64 = __t279 + __t461;
            let __t488: ::routh::__private::f64 = __t290 + __t464;
            let __t489: ::routh::__private::f64 = __t228 * __t484;
            let __t490: ::routh::__private::f64 = __t228 * __t486;
            let __t491: ::routh::__private::f64 = __t228 * __t488;
            let __t549: ::routh::__private::f64 = __v7 * __t452;
            let __t551: ::routh::__private::f64 = __v16 * __t229;
            let __t552: ::routh::__private::f64 = 2f64 * __t551;
            let __t553: ::routh::__private::f64 = __t549 + __t552;
            let __t554: ::routh::__private::f64 = __t484 * __t489;
            let __t556: ::routh::__private::f64 = __t553 - __t554;
            let __t557: ::routh::__private::f64 = __v8 * __t452;
            let __t559: ::routh::__private::f64 = __t229 * __t412;
            let __t560: ::routh::__private::f64 = __t557 + __t559;
            let __t561: ::routh::__private::f64 = __t486 * __t489;
            let __t563: ::routh::__private::f64 = __t560 - __t561;
            let __t564: ::routh::__private::f64 = __v9 * __t452;
            let __t566: ::routh::__private::f64 = __t229 * __t420;
            let __t567: ::routh::__private::f64 = __t564 + __t566;
            let __t568: ::routh::__private::f64 = __t488 * __t489;
            let __t570: ::routh::__private::f64 = __t567 - __t568;
            let __t571: ::routh::__private::f64 = __v10 * __t452;
            let __t573: ::routh::__private::f64 = __v20 * __t229;
            let __t574: ::routh::__private::f64 = 2f64 * __t573;
            let __t575: ::routh::__private::f64 = __t571 + __t574;
            let __t576: ::routh::__private::f64 = __t486 * __t490;
            let __t578: ::routh::__private::f64 = __t575 - __t576;
            let __t579: ::routh::__private::f64 = __v11 * __t452;
            let __t581: ::routh::__private::f64 = __t229 * __t437;
            let __t582: ::routh::__private::f64 = __t579 + __t581;
            let __t583: ::routh::__private::f64 = __t488 * __t490;
            let __t585: ::routh::__private::f64 = __t582 - __t583;
            let __t586: ::routh::__private::f64 = __v12 * __t452;
            let __t588: ::routh::__private::f64 = __v24 * __t229;
            let __t589: ::routh::__private::f64 = 2f64 * __t588;
            let __t590: ::routh::__private::f64 = __t586 + __t589;
            let __t591: ::routh::__private::f64 = __t488 * __t491;
            let __t593: ::routh::__private::f64 = __t590 - __t591;
            ::routh::__private::Matrix3::new(
                __t556,
                __t563,
                __t570,
                __t563,
                __t578,
                __t585,
                __t570,
                __t585,
                __t593,
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
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t637: ::routh::__private::f64 = __v6 - __t178;
            let __t638: ::routh::__private::f64 = __t637 / __t224;
            let __t640: ::routh::__private::f64 = __t637 * __t638;
            let __t642: ::routh::__private::f64 = (-0.5f64) * __t640;
            let __t643: ::routh::__private::f64 = __t642 - __t82;
            let __t861: ::routh::__private::f64 = -__t643;
            __t861
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
            let __t87: ::routh::__private::f64 = __t32 + __t36;
            let __t88: ::routh::__private::f64 = __t33 + __t87;
            let __t89: ::routh::__private::f64 = __t34 + __t88;
            let __t90: ::routh::__private::f64 = 0.5f64 * __t89;
            let __t91: ::routh::__private::f64 = __t68 + __t90;
            let __t92: ::routh::__private::f64 = __t38 + __t41;
            let __t93: ::routh::__private::f64 = __t37 + __t92;
            let __t94: ::routh::__private::f64 = __t39 + __t93;
            let __t95: ::routh::__private::f64 = 0.5f64 * __t94;
            let __t96: ::routh::__private::f64 = __t69 + __t95;
            let __t97: ::routh::__private::f64 = __t44 + __t46;
            let __t98: ::routh::__private::f64 = __t45 + __t97;
            let __t99: ::routh::__private::f64 = 0.5f64 * __t98;
            let __t100: ::routh::__private::f64 = __t70 + __t99;
            let __t101: ::routh::__private::f64 = __v25 * __t76;
            let __t103: ::routh::__private::f64 = __v1 * __v19;
            let __t104: ::routh::__private::f64 = __v0 * __v16;
            let __t105: ::routh::__private::f64 = __t103 + __t104;
            let __t106: ::routh::__private::f64 = __v2 * __v22;
            let __t107: ::routh::__private::f64 = __t105 + __t106;
            let __t108: ::routh::__private::f64 = __t107 - __t101;
            let __t109: ::routh::__private::f64 = __v26 * __t76;
            let __t111: ::routh::__private::f64 = __v1 * __v20;
            let __t112: ::routh::__private::f64 = __v0 * __v17;
            let __t113: ::routh::__private::f64 = __t111 + __t112;
            let __t114: ::routh::__private::f64 = __v2 * __v23;
            let __t115: ::routh::__private::f64 = __t113 + __t114;
            let __t116: ::routh::__private::f64 = __t115 - __t109;
            let __t117: ::routh::__private::f64 = __v27 * __t76;
            let __t119: ::routh::__private::f64 = __v1 * __v21;
            let __t120: ::routh::__private::f64 = __v0 * __v18;
            let __t121: ::routh::__private::f64 = __t119 + __t120;
            let __t122: ::routh::__private::f64 = __v2 * __v24;
            let __t123: ::routh::__private::f64 = __t121 + __t122;
            let __t124: ::routh::__private::f64 = __t123 - __t117;
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t207: ::routh::__private::f64 = __v4 * __t41;
            let __t208: ::routh::__private::f64 = __v1 * __t183;
            let __t209: ::routh::__private::f64 = __t207 + __t208;
            let __t210: ::routh::__private::f64 = __v3 * __t36;
            let __t211: ::routh::__private::f64 = __v0 * __t191;
            let __t212: ::routh::__private::f64 = __t210 + __t211;
            let __t213: ::routh::__private::f64 = __t209 + __t212;
            let __t214: ::routh::__private::f64 = __v5 * __t46;
            let __t215: ::routh::__private::f64 = __v2 * __t200;
            let __t216: ::routh::__private::f64 = __t214 + __t215;
            let __t217: ::routh::__private::f64 = __t213 + __t216;
            let __t218: ::routh::__private::f64 = 0.5f64 * __t217;
            let __t219: ::routh::__private::f64 = __t178 + __t218;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t227: ::routh::__private::f64 = __v6 - __t219;
            let __t228: ::routh::__private::f64 = 1.0f64 / __t224;
            let __t229: ::routh::__private::f64 = __t227 * __t228;
            let __t231: ::routh::__private::f64 = __t227 * __t229;
            let __t234: ::routh::__private::f64 = (-0.5f64) * __t231;
            let __t235: ::routh::__private::f64 = __t85 + __t234;
            let __t243: ::routh::__private::f64 = __t188 + __t191;
            let __t244: ::routh::__private::f64 = __t187 + __t243;
            let __t245: ::routh::__private::f64 = __t190 + __t244;
            let __t250: ::routh::__private::f64 = __t179 + __t183;
            let __t251: ::routh::__private::f64 = __t180 + __t250;
            let __t252: ::routh::__private::f64 = __t182 + __t251;
            let __t257: ::routh::__private::f64 = __t199 + __t200;
            let __t258: ::routh::__private::f64 = __t198 + __t257;
            let __t263: ::routh::__private::f64 = __v5 * __v22;
            let __t264: ::routh::__private::f64 = __t53 + __t68;
            let __t265: ::routh::__private::f64 = __v4 * __v19;
            let __t266: ::routh::__private::f64 = __t264 + __t265;
            let __t267: ::routh::__private::f64 = __t263 + __t266;
            let __t268: ::routh::__private::f64 = __t90 + __t267;
            let __t274: ::routh::__private::f64 = __v5 * __v23;
            let __t275: ::routh::__private::f64 = __v3 * __v17;
            let __t276: ::routh::__private::f64 = __t59 + __t69;
            let __t277: ::routh::__private::f64 = __t275 + __t276;
            let __t278: ::routh::__private::f64 = __t274 + __t277;
            let __t279: ::routh::__private::f64 = __t95 + __t278;
            let __t285: ::routh::__private::f64 = __t65 + __t70;
            let __t286: ::routh::__private::f64 = __v3 * __v18;
            let __t287: ::routh::__private::f64 = __v4 * __v21;
            let __t288: ::routh::__private::f64 = __t286 + __t287;
            let __t289: ::routh::__private::f64 = __t285 + __t288;
            let __t290: ::routh::__private::f64 = __t99 + __t289;
            let __t303: ::routh::__private::f64 = __t228 * __t245;
            let __t305: ::routh::__private::f64 = __t228 * __t252;
            let __t307: ::routh::__private::f64 = __t228 * __t258;
            let __t312: ::routh::__private::f64 = __t245 * __t303;
            let __t317: ::routh::__private::f64 = (-0.25f64) * __t312;
            let __t318: ::routh::__private::f64 = __v7 + __t317;
            let __t319: ::routh::__private::f64 = __t252 * __t303;
            let __t322: ::routh::__private::f64 = (-0.25f64) * __t319;
            let __t323: ::routh::__private::f64 = __v8 + __t322;
            let __t324: ::routh::__private::f64 = __t258 * __t303;
            let __t327: ::routh::__private::f64 = (-0.25f64) * __t324;
            let __t328: ::routh::__private::f64 = __v9 + __t327;
            let __t350: ::routh::__private::f64 = __t252 * __t305;
            let __t353: ::routh::__private::f64 = (-0.25f64) * __t350;
            let __t354: ::routh::__private::f64 = __v10 + __t353;
            let __t355: ::routh::__private::f64 = __t258 * __t305;
            let __t358: ::routh::__private::f64 = (-0.25f64) * __t355;
            let __t359: ::routh::__private::f64 = __v11 + __t358;
            let __t379: ::routh::__private::f64 = __t258 * __t307;
            let __t382: ::routh::__private::f64 = (-0.25f64) * __t379;
            let __t383: ::routh::__private::f64 = __v12 + __t382;
            let __t412: ::routh::__private::f64 = __v17 + __v19;
            let __t420: ::routh::__private::f64 = __v18 + __v22;
            let __t437: ::routh::__private::f64 = __v21 + __v23;
            let __t452: ::routh::__private::f64 = __t229 * __t229;
            let __t458: ::routh::__private::f64 = __t229 * __t245;
            let __t459: ::routh::__private::f64 = 0.5f64 * __t458;
            let __t460: ::routh::__private::f64 = __t91 + __t459;
            let __t461: ::routh::__private::f64 = __t229 * __t252;
            let __t462: ::routh::__private::f64 = 0.5f64 * __t461;
            let __t463: ::routh::__private::f64 = __t96 + __t462;
            let __t464: ::routh::__private::f64 = __t229 * __t258;
            let __t465: ::routh::__private::f64 = 0.5f64 * __t464;
            let __t466: ::routh::__private::f64 = __t100 + __t465;
            let __t467: ::routh::__private::f64 = __t229 * __t268;
            let __t468: ::routh::__private::f64 = __t108 + __t467;
            let __t469: ::routh::__private::f64 = __t245 * __t452;
            let __t470: ::routh::__private::f64 = 0.5f64 * __t469;
            let __t471: ::routh::__private::f64 = __t468 + __t470;
            let __t472: ::routh::__private::f64 = __t229 * __t279;
            let __t473: ::routh::__private::f64 = __t116 + __t472;
            let __t474: ::routh::__private::f64 = __t252 * __t452;
            let __t475: ::routh::__private::f64 = 0.5f64 * __t474;
            let __t476: ::routh::__private::f64 = __t473 + __t475;
            let __t477: ::routh::__private::f64 = __t229 * __t290;
            let __t478: ::routh::__private::f64 = __t124 + __t477;
            let __t479: ::routh::__private::f64 = __t258 * __t452;
            let __t480: ::routh::__private::f64 = 0.5f64 * __t479;
            let __t481: ::routh::__private::f64 = __t478 + __t480;
            let __t484: ::routh::__private::f64 = __t268 + __t458;
            let __t486: ::routh::__private::f64 = __t279 + __t461;
            let __t488: ::routh::__private::f64 = __t290 + __t464;
            let __t489: ::routh::__private::f64 = __t228 * __t484;
            let __t490: ::routh::__private::f64 = __t228 * __t486;
            let __t491: ::routh::__private::f64 = __t228 * __t488;
            let __t492: ::routh::__private::f64 = __v7 * __t229;
            let __t494: ::routh::__private::f64 = __v16 + __t492;
            let __t495: ::routh::__private::f64 = __t303 * __t484;
            let __t497: ::routh::__private::f64 = (-0.5f64) * __t495;
            let __t498: ::routh::__private::f64 = __t494 + __t497;
            let __t499: ::routh::__private::f64 = __v8 * __t229;
            let __t501: ::routh::__private::f64 = __v17 + __t499;
            let __t502: ::routh::__private::f64 = __t303 * __t486;
            let __t504: ::routh::__private::f64 = (-0.5f64) * __t502;
            let __t505: ::routh::__private::f64 = __t501 + __t504;
            let __t506: ::routh::__private::f64 = __v9 * __t229;
            let __t508: ::routh::__private::f64 = __v18 + __t506;
            let __t509: ::routh::__private::f64 = __t303 * __t488;
            let __t511: ::routh::__private::f64 = (-0.5f64) * __t509;
            let __t512: ::routh::__private::f64 = __t508 + __t511;
            let __t513: ::routh::__private::f64 = __v19 + __t499;
            let __t514: ::routh::__private::f64 = __t305 * __t484;
            let __t516: ::routh::__private::f64 = (-0.5f64) * __t514;
            let __t517: ::routh::__private::f64 = __t513 + __t516;
            let __t518: ::routh::__private::f64 = __v10 * __t229;
            let __t520: ::routh::__private::f64 = __v20 + __t518;
            let __t521: ::routh::__private::f64 = __t305 * __t486;
            let __t523: ::routh::__private::f64 = (-0.5f64) * __t521;
            let __t524: ::routh::__private::f64 = __t520 + __t523;
            let __t525: ::routh::__private::f64 = __v11 * __t229;
            let __t527: ::routh::__private::f64 = __v21 + __t525;
            let __t528: ::routh::__private::f64 = __t305 * __t488;
            let __t530: ::routh::__private::f64 = (-0.5f64) * __t528;
            let __t531: ::routh::__private::f64 = __t527 + __t530;
            let __t532: ::routh::__private::f64 = __v22 + __t506;
            let __t533: ::routh::__private::f64 = __t307 * __t484;
            let __t535: ::routh::__private::f64 = (-0.5f64) * __t533;
            let __t536: ::routh::__private::f64 = __t532 + __t535;
            let __t537: ::routh::__private::f64 = __v23 + __t525;
            let __t538: ::routh::__private::f64 = __t307 * __t486;
            let __t540: ::routh::__private::f64 = (-0.5f64) * __t538;
            let __t541: ::routh::__private::f64 = __t537 + __t540;
            let __t542: ::routh::__private::f64 = __v12 * __t229;
            let __t544: ::routh::__private::f64 = __v24 + __t542;
            let __t545: ::routh::__private::f64 = __t307 * __t488;
            let __t547: ::routh::__private::f64 = (-0.5f64) * __t545;
            let __t548: ::routh::__private::f64 = __t544 + __t547;
            let __t549: ::routh::__private::f64 = __v7 * __t452;
            let __t551: ::routh::__private::f64 = __v16 * __t229;
            let __t552: ::routh::__private::f64 = 2f64 * __t551;
            let __t553: ::routh::__private::f64 = __t549 + __t552;
            let __t554: ::routh::__private::f64 = __t484 * __t489;
            let __t556: ::routh::__private::f64 = __t553 - __t554;
            let __t557: ::routh::__private::f64 = __v8 * __t452;
            let __t559: ::routh::__private::f64 = __t229 * __t412;
            let __t560: ::routh::__private::f64 = __t557 + __t559;
            let __t561: ::routh::__private::f64 = __t486 * __t489;
            let __t563: ::routh::__private::f64 = __t560 - __t561;
            let __t564: ::routh::__private::f64 = __v9 * __t452;
            let __t566: ::routh::__private::f64 = __t229 * __t420;
            let __t567: ::routh::__private::f64 = __t564 + __t566;
            let __t568: ::routh::__private::f64 = __t488 * __t489;
            let __t570: ::routh::__private::f64 = __t567 - __t568;
            let __t571: ::routh::__private::f64 = __v10 * __t452;
            let __t573: ::routh::__private::f64 = __v20 * __t229;
            let __t574: ::routh::__private::f64 = 2f64 * __t573;
            let __t575: ::routh::__private::f64 = __t571 + __t574;
            let __t576: ::routh::__private::f64 = __t486 * __t490;
            let __t578: ::routh::__private::f64 = __t575 - __t576;
            let __t579: ::routh::__private::f64 = __v11 * __t452;
            let __t581: ::routh::__private::f64 = __t229 * __t437;
            let __t582: ::routh::__private::f64 = __t579 + __t581;
            let __t583: ::routh::__private::f64 = __t488 * __t490;
            let __t585: ::routh::__private::f64 = __t582 - __t583;
            let __t586: ::routh::__private::f64 = __v12 * __t452;
            let __t588: ::routh::__private::f64 = __v24 * __t229;
            let __t589: ::routh::__private::f64 = 2f64 * __t588;
            let __t590: ::routh::__private::f64 = __t586 + __t589;
            let __t591: ::routh::__private::f64 = __t488 * __t491;
            let __t593: ::routh::__private::f64 = __t590 - __t591;
            let __t594: ::routh::__private::f64 = -__t229;
            ::routh::__private::RouthBundle {
                routhian: __t235,
                psi_dot: __t229,
                dr_domega: ::routh::__private::Vector3::new(__t460, __t463, __t466),
                dr_dgamma: ::routh::__private::Vector3::new(__t471, __t476, __t481),
                dr_dp: __t594,
                d2r_domega2: ::routh::__private::Matrix3::new(
                    __t318,
                    __t323,
                    __t328,
                    __t323,
                    __t354,
                    __t359,
                    __t328,
                    __t359,
                    __t383,
                ),
                d2r_domega_dgamma: ::routh::__private::Matrix3::new(
                    __t498,
                    __t505,
                    __t512,
                    __t517,
                    __t524,
                    __t531,
                    __t536,
                    __t541,
                    __t548,
                ),
                d2r_dgamma2: ::routh::__private::Matrix3::new(
                    __t556,
                    __t563,
                    __t570,
                    __t563,
                    __t578,
                    __t585,
                    __t570,
                    __t585,
                    __t593,
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
            let __t101: ::routh::__private::f64 = __v25 * __t76;
            let __t109: ::routh::__private::f64 = __v26 * __t76;
            let __t117: ::routh::__private::f64 = __v27 * __t76;
            let __t174: ::routh::__private::f64 = __v4 * __t69;
            let __t175: ::routh::__private::f64 = __v3 * __t68;
            let __t176: ::routh::__private::f64 = __t174 + __t175;
            let __t177: ::routh::__private::f64 = __v5 * __t70;
            let __t178: ::routh::__private::f64 = __t176 + __t177;
            let __t179: ::routh::__private::f64 = __v4 * __v10;
            let __t180: ::routh::__private::f64 = __v3 * __v8;
            let __t181: ::routh::__private::f64 = __t179 + __t180;
            let __t182: ::routh::__private::f64 = __v5 * __v11;
            let __t183: ::routh::__private::f64 = __t181 + __t182;
            let __t187: ::routh::__private::f64 = __v4 * __v8;
            let __t188: ::routh::__private::f64 = __v3 * __v7;
            let __t189: ::routh::__private::f64 = __t187 + __t188;
            let __t190: ::routh::__private::f64 = __v5 * __v9;
            let __t191: ::routh::__private::f64 = __t189 + __t190;
            let __t196: ::routh::__private::f64 = __v4 * __v11;
            let __t197: ::routh::__private::f64 = __v3 * __v9;
            let __t198: ::routh::__private::f64 = __t196 + __t197;
            let __t199: ::routh::__private::f64 = __v5 * __v12;
            let __t200: ::routh::__private::f64 = __t198 + __t199;
            let __t220: ::routh::__private::f64 = __v3 * __t191;
            let __t221: ::routh::__private::f64 = __v4 * __t183;
            let __t222: ::routh::__private::f64 = __v5 * __t200;
            let __t223: ::routh::__private::f64 = __t220 + __t221;
            let __t224: ::routh::__private::f64 = __t222 + __t223;
            let __t228: ::routh::__private::f64 = 1.0f64 / __t224;
            let __t243: ::routh::__private::f64 = __t188 + __t191;
            let __t244: ::routh::__private::f64 = __t187 + __t243;
            let __t245: ::routh::__private::f64 = __t190 + __t244;
            let __t250: ::routh::__private::f64 = __t179 + __t183;
            let __t251: ::routh::__private::f64 = __t180 + __t250;
            let __t252: ::routh::__private::f64 = __t182 + __t251;
            let __t257: ::routh::__private::f64 = __t199 + __t200;
            let __t258: ::routh::__private::f64 = __t198 + __t257;
            let __t263: ::routh::__private::f64 = __v5 * __v22;
            let __t264: ::routh::__private::f64 = __t53 + __t68;
            let __t265: ::routh::__private::f64 = __v4 * __v19;
            let __t266: ::routh::__private::f64 = __t264 + __t265;
            let __t267: ::routh::__private::f64 = __t263 + __t266;
            let __t274: ::routh::__private::f64 = __v5 * __v23;
            let __t275: ::routh::__private::f64 = __v3 * __v17;
            let __t276: ::routh::__private::f64 = __t59 + __t69;
            let __t277: ::routh::__private::f64 = __t275 + __t276;
            let __t278: ::routh::__private::f64 = __t274 + __t277;
            let __t285: ::routh::__private::f64 = __t65 + __t70;
            let __t286: ::routh::__private::f64 = __v3 * __v18;
            let __t287: ::routh::__private::f64 = __v4 * __v21;
            let __t288: ::routh::__private::f64 = __t286 + __t287;
            let __t289: ::routh::__private::f64 = __t285 + __t288;
            let __t303: ::routh::__private::f64 = __t228 * __t245;
            let __t305: ::routh::__private::f64 = __t228 * __t252;
            let __t307: ::routh::__private::f64 = __t228 * __t258;
            let __t312: ::routh::__private::f64 = __t245 * __t303;
            let __t317: ::routh::__private::f64 = (-0.25f64) * __t312;
            let __t318: ::routh::__private::f64 = __v7 + __t317;
            let __t319: ::routh::__private::f64 = __t252 * __t303;
            let __t322: ::routh::__private::f64 = (-0.25f64) * __t319;
            let __t323: ::routh::__private::f64 = __v8 + __t322;
            let __t324: ::routh::__private::f64 = __t258 * __t303;
            let __t327: ::routh::__private::f64 = (-0.25f64) * __t324;
            let __t328: ::routh::__private::f64 = __v9 + __t327;
            let __t350: ::routh::__private::f64 = __t252 * __t305;
            let __t353: ::routh::__private::f64 = (-0.25f64) * __t350;
            let __t354: ::routh::__private::f64 = __v10 + __t353;
            let __t355: ::routh::__private::f64 = __t258 * __t305;
            let __t358: ::routh::__private::f64 = (-0.25f64) * __t355;
            let __t359: ::routh::__private::f64 = __v11 + __t358;
            let __t379: ::routh::__private::f64 = __t258 * __t307;
            let __t382: ::routh::__private::f64 = (-0.25f64) * __t379;
            let __t383: ::routh::__private::f64 = __v12 + __t382;
            let __t412: ::routh::__private::f64 = __v17 + __v19;
            let __t420: ::routh::__private::f64 = __v18 + __v22;
            let __t437: ::routh::__private::f64 = __v21 + __v23;
            let __t637: ::routh::__private::f64 = __v6 - __t178;
            let __t638: ::routh::__private::f64 = __t228 * __t637;
            let __t719: ::routh::__private::f64 = __t638 * __t638;
            let __t725: ::routh::__private::f64 = __t245 * __t638;
            let __t726: ::routh::__private::f64 = 0.5f64 * __t725;
            let __t727: ::routh::__private::f64 = __t68 + __t726;
            let __t728: ::routh::__private::f64 = __t252 * __t638;
            let __t729: ::routh::__private::f64 = 0.5f64 * __t728;
            let __t730: ::routh::__private::f64 = __t69 + __t729;
            let __t731: ::routh::__private::f64 = __t258 * __t638;
            let __t732: ::routh::__private::f64 = 0.5f64 * __t731;
            let __t733: ::routh::__private::f64 = __t70 + __t732;
            let __t734: ::routh::__private::f64 = __t267 * __t638;
            let __t735: ::routh::__private::f64 = __t734 - __t101;
            let __t736: ::routh::__private::f64 = __t245 * __t719;
            let __t737: ::routh::__private::f64 = 0.5f64 * __t736;
            let __t738: ::routh::__private::f64 = __t735 + __t737;
            let __t739: ::routh::__private::f64 = __t278 * __t638;
            let __t740: ::routh::__private::f64 = __t739 - __t109;
            let __t741: ::routh::__private::f64 = __t252 * __t719;
            let __t742: ::routh::__private::f64 = 0.5f64 * __t741;
            let __t743: ::routh::__private::f64 = __t740 + __t742;
            let __t744: ::routh::__private::f64 = __t289 * __t638;
            let __t745: ::routh::__private::f64 = __t744 - __t117;
            let __t746: ::routh::__private::f64 = __t258 * __t719;
            let __t747: ::routh::__private::f64 = 0.5f64 * __t746;
            let __t748: ::routh::__private::f64 = __t745 + __t747;
            let __t751: ::routh::__private::f64 = __t267 + __t725;
            let __t753: ::routh::__private::f64 = __t278 + __t728;
            let __t755: ::routh::__private::f64 = __t289 + __t731;
            let __t756: ::routh::__private::f64 = __t228 * __t751;
            let __t757: ::routh::__private::f64 = __t228 * __t753;
            let __t758: ::routh::__private::f64 = __t228 * __t755;
            let __t759: ::routh::__private::f64 = __v7 * __t638;
            let __t761: ::routh::__private::f64 = __v16 + __t759;
            let __t762: ::routh::__private::f64 = __t303 * __t751;
            let __t764: ::routh::__private::f64 = (-0.5f64) * __t762;
            let __t765: ::routh::__private::f64 = __t761 + __t764;
            let __t766: ::routh::__private::f64 = __v8 * __t638;
            let __t768: ::routh::__private::f64 = __v17 + __t766;
            let __t769: ::routh::__private::f64 = __t303 * __t753;
            let __t771: ::routh::__private::f64 = (-0.5f64) * __t769;
            let __t772: ::routh::__private::f64 = __t768 + __t771;
            let __t773: ::routh::__private::f64 = __v9 * __t638;
            let __t775: ::routh::__private::f64 = __v18 + __t773;
            let __t776: ::routh::__private::f64 = __t303 * __t755;
            let __t778: ::routh::__private::f64 = (-0.5f64) * __t776;
            let __t779: ::routh::__private::f64 = __t775 + __t778;
            let __t780: ::routh::__private::f64 = __v19 + __t766;
            let __t781: ::routh::__private::f64 = __t305 * __t751;
            let __t783: ::routh::__private::f64 = (-0.5f64) * __t781;
            let __t784: ::routh::__private::f64 = __t780 + __t783;
            let __t785: ::routh::__private::f64 = __v10 * __t638;
            let __t787: ::routh::__private::f64 = __v20 + __t785;
            let __t788: ::routh::__private::f64 = __t305 * __t753;
            let __t790: ::routh::__private::f64 = (-0.5f64) * __t788;
            let __t791: ::routh::__private::f64 = __t787 + __t790;
            let __t792: ::routh::__private::f64 = __v11 * __t638;
            let __t794: ::routh::__private::f64 = __v21 + __t792;
            let __t795: ::routh::__private::f64 = __t305 * __t755;
            let __t797: ::routh::__private::f64 = (-0.5f64) * __t795;
            let __t798: ::routh::__private::f64 = __t794 + __t797;
            let __t799: ::routh::__private::f64 = __v22 + __t773;
            let __t800: ::routh::__private::f64 = __t307 * __t751;
            let __t802: ::routh::__private::f64 = (-0.5f64) * __t800;
            let __t803: ::routh::__private::f64 = __t799 + __t802;
            let __t804: ::routh::__private::f64 = __v23 + __t792;
            let __t805: ::routh::__private::f64 = __t307 * __t753;
            let __t807: ::routh::__private::f64 = (-0.5f64) * __t805;
            let __t808: ::routh::__private::f64 = __t804 + __t807;
            let __t809: ::routh::__private::f64 = __v12 * __t638;
            let __t811: ::routh::__private::f64 = __v24 + __t809;
            let __t812: ::routh::__private::f64 = __t307 * __t755;
            let __t814: ::routh::__private::f64 = (-0.5f64) * __t812;
            let __t815: ::routh::__private::f64 = __t811 + __t814;
            let __t816: ::routh::__private::f64 = __v7 * __t719;
            let __t818: ::routh::__private::f64 = __v16 * __t638;
            let __t819: ::routh::__private::f64 = 2f64 * __t818;
            let __t820: ::routh::__private::f64 = __t816 + __t819;
            let __t821: ::routh::__private::f64 = __t751 * __t756;
            let __t823: ::routh::__private::f64 = __t820 - __t821;
            let __t824: ::routh::__private::f64 = __v8 * __t719;
            let __t826: ::routh::__private::f64 = __t412 * __t638;
            let __t827: ::routh::__private::f64 = __t824 + __t826;
            let __t828: ::routh::__private::f64 = __t753 * __t756;
            let __t830: ::routh::__private::f64 = __t827 - __t828;
            let __t831: ::routh::__private::f64 = __v9 * __t719;
            let __t833: ::routh::__private::f64 = __t420 * __t638;
            let __t834: ::routh::__private::f64 = __t831 + __t833;
            let __t835: ::routh::__private::f64 = __t755 * __t756;
            let __t837: ::routh::__private::f64 = __t834 - __t835;
            let __t838: ::routh::__private::f64 = __v10 * __t719;
            let __t840: ::routh::__private::f64 = __v20 * __t638;
            let __t841: ::routh::__private::f64 = 2f64 * __t840;
            let __t842: ::routh::__private::f64 = __t838 + __t841;
            let __t843: ::routh::__private::f64 = __t753 * __t757;
            let __t845: ::routh::__private::f64 = __t842 - __t843;
            let __t846: ::routh::__private::f64 = __v11 * __t719;
            let __t848: ::routh::__private::f64 = __t437 * __t638;
            let __t849: ::routh::__private::f64 = __t846 + __t848;
            let __t850: ::routh::__private::f64 = __t755 * __t757;
            let __t852: ::routh::__private::f64 = __t849 - __t850;
            let __t853: ::routh::__private::f64 = __v12 * __t719;
            let __t855: ::routh::__private::f64 = __v24 * __t638;
            let __t856: ::routh::__private::f64 = 2f64 * __t855;
            let __t857: ::routh::__private::f64 = __t853 + __t856;
            let __t858: ::routh::__private::f64 = __t755 * __t758;
            let __t860: ::routh::__private::f64 = __t857 - __t858;
            let __t868: ::routh::__private::f64 = __v5 * __t772;
            let __t869: ::routh::__private::f64 = __v4 * __t779;
            let __t871: ::routh::__private::f64 = __t868 - __t869;
            let __t872: ::routh::__private::f64 = __v5 * __t765;
            let __t874: ::routh::__private::f64 = __v3 * __t779;
            let __t875: ::routh::__private::f64 = __t874 - __t872;
            let __t876: ::routh::__private::f64 = __v4 * __t765;
            let __t877: ::routh::__private::f64 = __v3 * __t772;
            let __t879: ::routh::__private::f64 = __t876 - __t877;
            let __t880: ::routh::__private::f64 = __v5 * __t791;
            let __t881: ::routh::__private::f64 = __v4 * __t798;
            let __t883: ::routh::__private::f64 = __t880 - __t881;
            let __t884: ::routh::__private::f64 = __v5 * __t784;
            let __t886: ::routh::__private::f64 = __v3 * __t798;
            let __t887: ::routh::__private::f64 = __t886 - __t884;
            let __t888: ::routh::__private::f64 = __v4 * __t784;
            let __t889: ::routh::__private::f64 = __v3 * __t791;
            let __t891: ::routh::__private::f64 = __t888 - __t889;
            let __t892: ::routh::__private::f64 = __v5 * __t808;
            let __t893: ::routh::__private::f64 = __v4 * __t815;
            let __t895: ::routh::__private::f64 = __t892 - __t893;
            let __t896: ::routh::__private::f64 = __v5 * __t803;
            let __t898: ::routh::__private::f64 = __v3 * __t815;
            let __t899: ::routh::__private::f64 = __t898 - __t896;
            let __t900: ::routh::__private::f64 = __v4 * __t803;
            let __t901: ::routh::__private::f64 = __v3 * __t808;
            let __t903: ::routh::__private::f64 = __t900 - __t901;
            let __t905: ::routh::__private::f64 = __t869 - __t868;
            let __t907: ::routh::__private::f64 = __t881 - __t880;
            let __t909: ::routh::__private::f64 = __t893 - __t892;
            let __t911: ::routh::__private::f64 = __t872 - __t874;
            let __t913: ::routh::__private::f64 = __t884 - __t886;
            let __t915: ::routh::__private::f64 = __t896 - __t898;
            let __t917: ::routh::__private::f64 = __t877 - __t876;
            let __t919: ::routh::__private::f64 = __t889 - __t888;
            let __t921: ::routh::__private::f64 = __t901 - __t900;
            let __t922: ::routh::__private::f64 = __t871 + __t905;
            let __t923: ::routh::__private::f64 = 0.5f64 * __t922;
            let __t924: ::routh::__private::f64 = __t875 + __t907;
            let __t925: ::routh::__private::f64 = __t733 + __t924;
            let __t926: ::routh::__private::f64 = 0.5f64 * __t925;
            let __t927: ::routh::__private::f64 = __t879 + __t909;
            let __t928: ::routh::__private::f64 = __t927 - __t730;
            let __t929: ::routh::__private::f64 = 0.5f64 * __t928;
            let __t930: ::routh::__private::f64 = __t883 + __t911;
            let __t931: ::routh::__private::f64 = __t930 - __t733;
            let __t932: ::routh::__private::f64 = 0.5f64 * __t931;
            let __t933: ::routh::__private::f64 = __t887 + __t913;
            let __t934: ::routh::__private::f64 = 0.5f64 * __t933;
            let __t935: ::routh::__private::f64 = __t891 + __t915;
            let __t936: ::routh::__private::f64 = __t727 + __t935;
            let __t937: ::routh::__private::f64 = 0.5f64 * __t936;
            let __t938: ::routh::__private::f64 = __t895 + __t917;
            let __t939: ::routh::__private::f64 = __t730 + __t938;
            let __t940: ::routh::__private::f64 = 0.5f64 * __t939;
            let __t941: ::routh::__private::f64 = __t899 + __t919;
            let __t942: ::routh::__private::f64 = __t941 - __t727;
            let __t943: ::routh::__private::f64 = 0.5f64 * __t942;
            let __t944: ::routh::__private::f64 = __t903 + __t921;
            let __t945: ::routh::__private::f64 = 0.5f64 * __t944;
            let __t946: ::routh::__private::f64 = __v3 * __t738;
            let __t947: ::routh::__private::f64 = __v4 * __t743;
            let __t948: ::routh::__private::f64 = __v5 * __t748;
            let __t949: ::routh::__private::f64 = __t946 + __t947;
            let __t950: ::routh::__private::f64 = __t948 + __t949;
            let __t952: ::routh::__private::f64 = __t950 - __t823;
            let __t956: ::routh::__private::f64 = __t950 - __t845;
            let __t959: ::routh::__private::f64 = __t950 - __t860;
            let __t960: ::routh::__private::f64 = __v5 * __t830;
            let __t962: ::routh::__private::f64 = __v4 * __t837;
            let __t964: ::routh::__private::f64 = __t962 - __t960;
            let __t965: ::routh::__private::f64 = __v5 * __t956;
            let __t966: ::routh::__private::f64 = __v4 * __t852;
            let __t968: ::routh::__private::f64 = __t965 + __t966;
            let __t969: ::routh::__private::f64 = __v5 * __t852;
            let __t971: ::routh::__private::f64 = __v4 * __t959;
            let __t973: ::routh::__private::f64 = __t969 + __t971;
            let __t975: ::routh::__private::f64 = __v5 * __t952;
            let __t977: ::routh::__private::f64 = __v3 * __t837;
            let __t979: ::routh::__private::f64 = __t975 + __t977;
            let __t981: ::routh::__private::f64 = __v3 * __t852;
            let __t983: ::routh::__private::f64 = __t960 - __t981;
            let __t984: ::routh::__private::f64 = __v5 * __t837;
            let __t986: ::routh::__private::f64 = __v3 * __t959;
            let __t987: ::routh::__private::f64 = __t984 + __t986;
            let __t988: ::routh::__private::f64 = __v4 * __t952;
            let __t989: ::routh::__private::f64 = __v3 * __t830;
            let __t991: ::routh::__private::f64 = __t988 + __t989;
            let __t992: ::routh::__private::f64 = __v4 * __t830;
            let __t994: ::routh::__private::f64 = __v3 * __t956;
            let __t996: ::routh::__private::f64 = __t992 + __t994;
            let __t998: ::routh::__private::f64 = __t981 - __t962;
            let __t999: ::routh::__private::f64 = __v5 * __t968;
            let __t1000: ::routh::__private::f64 = __v4 * __t973;
            let __t1002: ::routh::__private::f64 = __t999 + __t1000;
            let __t1003: ::routh::__private::f64 = __v5 * __t964;
            let __t1005: ::routh::__private::f64 = __v3 * __t973;
            let __t1007: ::routh::__private::f64 = __t1003 + __t1005;
            let __t1008: ::routh::__private::f64 = -__t1007;
            let __t1009: ::routh::__private::f64 = __v4 * __t964;
            let __t1010: ::routh::__private::f64 = __v3 * __t968;
            let __t1012: ::routh::__private::f64 = __t1009 - __t1010;
            let __t1013: ::routh::__private::f64 = __v5 * __t983;
            let __t1014: ::routh::__private::f64 = __v4 * __t987;
            let __t1016: ::routh::__private::f64 = __t1013 - __t1014;
            let __t1017: ::routh::__private::f64 = __v5 * __t979;
            let __t1019: ::routh::__private::f64 = __v3 * __t987;
            let __t1020: ::routh::__private::f64 = __t1017 + __t1019;
            let __t1021: ::routh::__private::f64 = __v4 * __t979;
            let __t1023: ::routh::__private::f64 = __v3 * __t983;
            let __t1025: ::routh::__private::f64 = __t1021 + __t1023;
            let __t1026: ::routh::__private::f64 = -__t1025;
            let __t1027: ::routh::__private::f64 = __v5 * __t996;
            let __t1029: ::routh::__private::f64 = __v4 * __t998;
            let __t1031: ::routh::__private::f64 = __t1027 + __t1029;
            let __t1032: ::routh::__private::f64 = -__t1031;
            let __t1033: ::routh::__private::f64 = __v5 * __t991;
            let __t1035: ::routh::__private::f64 = __v3 * __t998;
            let __t1036: ::routh::__private::f64 = __t1035 - __t1033;
            let __t1037: ::routh::__private::f64 = __v4 * __t991;
            let __t1038: ::routh::__private::f64 = __v3 * __t996;
            let __t1040: ::routh::__private::f64 = __t1037 + __t1038;
            ::routh::__private::GyroscopicSystem {
                a: ::routh::__private::Matrix3::new(
                    __t318,
                    __t323,
                    __t328,
                    __t323,
                    __t354,
                    __t359,
                    __t328,
                    __t359,
                    __t383,
                ),
                g: ::routh::__private::Matrix3::new(
                    __t923,
                    __t926,
                    __t929,
                    __t932,
                    __t934,
                    __t937,
                    __t940,
                    __t943,
                    __t945,
                ),
                c: ::routh::__private::Matrix3::new(
                    __t1002,
                    __t1008,
                    __t1012,
                    __t1016,
                    __t1020,
                    __t1026,
                    __t1032,
                    __t1036,
                    __t1040,
                ),
            }
        }
    }
};
