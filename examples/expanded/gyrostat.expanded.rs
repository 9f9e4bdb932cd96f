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
    type __F64 = ::routh::__private::f64;
    type __Vector3 = ::routh::__private::Vector3<::routh::__private::f64>;
    type __Matrix3 = ::routh::__private::Matrix3<::routh::__private::f64>;
    type __RouthBundle = ::routh::__private::RouthBundle;
    type __GyroscopicSystem = ::routh::__private::GyroscopicSystem;
    #[automatically_derived]
    impl ::routh::__private::Lagrangian for Gyrostat {
        #[inline]
        fn lagrangian(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v0 * __t36;
            let __t48: __F64 = __v1 * __t41;
            let __t49: __F64 = __v2 * __t46;
            let __t50: __F64 = __t47 + __t48;
            let __t51: __F64 = __t49 + __t50;
            let __t52: __F64 = 0.5f64 * __t51;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t71: __F64 = __v0 * __t68;
            let __t72: __F64 = __v1 * __t69;
            let __t73: __F64 = __v2 * __t70;
            let __t74: __F64 = __t71 + __t72;
            let __t75: __F64 = __t73 + __t74;
            let __t76: __F64 = __v28 * __v29;
            let __t77: __F64 = __v3 * __v25;
            let __t78: __F64 = __v4 * __v26;
            let __t79: __F64 = __v5 * __v27;
            let __t80: __F64 = __t77 + __t78;
            let __t81: __F64 = __t79 + __t80;
            let __t82: __F64 = __t76 * __t81;
            let __t84: __F64 = __t75 - __t82;
            let __t85: __F64 = __t52 + __t84;
            __t85
        }
        #[inline]
        fn dl_domega(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            __Vector3::new(__t91, __t95, __t99)
        }
        #[inline]
        fn dl_dgamma(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t76: __F64 = __v28 * __v29;
            let __t100: __F64 = __v25 * __t76;
            let __t102: __F64 = __v1 * __v19;
            let __t103: __F64 = __v0 * __v16;
            let __t104: __F64 = __t102 + __t103;
            let __t105: __F64 = __v2 * __v22;
            let __t106: __F64 = __t104 + __t105;
            let __t107: __F64 = __t106 - __t100;
            let __t108: __F64 = __v26 * __t76;
            let __t110: __F64 = __v1 * __v20;
            let __t111: __F64 = __v0 * __v17;
            let __t112: __F64 = __t110 + __t111;
            let __t113: __F64 = __v2 * __v23;
            let __t114: __F64 = __t112 + __t113;
            let __t115: __F64 = __t114 - __t108;
            let __t116: __F64 = __v27 * __t76;
            let __t118: __F64 = __v1 * __v21;
            let __t119: __F64 = __v0 * __v18;
            let __t120: __F64 = __t118 + __t119;
            let __t121: __F64 = __v2 * __v24;
            let __t122: __F64 = __t120 + __t121;
            let __t123: __F64 = __t122 - __t116;
            __Vector3::new(__t107, __t115, __t123)
        }
        #[inline]
        fn d2l_domega2(&self, __gamma: &__Vector3) -> __Matrix3 {
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            __Matrix3::new(__v7, __v8, __v9, __v8, __v10, __v11, __v9, __v11, __v12)
        }
        #[inline]
        fn d2l_domega_dgamma(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __Matrix3 {
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            __Matrix3::new(__v16, __v17, __v18, __v19, __v20, __v21, __v22, __v23, __v24)
        }
        #[inline]
        fn energy(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v0 * __t36;
            let __t48: __F64 = __v1 * __t41;
            let __t49: __F64 = __v2 * __t46;
            let __t50: __F64 = __t47 + __t48;
            let __t51: __F64 = __t49 + __t50;
            let __t52: __F64 = 0.5f64 * __t51;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t71: __F64 = __v0 * __t68;
            let __t72: __F64 = __v1 * __t69;
            let __t73: __F64 = __v2 * __t70;
            let __t74: __F64 = __t71 + __t72;
            let __t75: __F64 = __t73 + __t74;
            let __t76: __F64 = __v28 * __v29;
            let __t77: __F64 = __v3 * __v25;
            let __t78: __F64 = __v4 * __v26;
            let __t79: __F64 = __v5 * __v27;
            let __t80: __F64 = __t77 + __t78;
            let __t81: __F64 = __t79 + __t80;
            let __t82: __F64 = __t76 * __t81;
            let __t84: __F64 = __t75 - __t82;
            let __t85: __F64 = __t52 + __t84;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t124: __F64 = __v0 * __t91;
            let __t125: __F64 = __v1 * __t95;
            let __t126: __F64 = __v2 * __t99;
            let __t127: __F64 = __t124 + __t125;
            let __t128: __F64 = __t126 + __t127;
            let __t130: __F64 = __t128 - __t85;
            __t130
        }
        #[inline]
        fn cyclic_momentum(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t131: __F64 = __v3 * __t91;
            let __t132: __F64 = __v4 * __t95;
            let __t133: __F64 = __v5 * __t99;
            let __t134: __F64 = __t131 + __t132;
            let __t135: __F64 = __t133 + __t134;
            __t135
        }
    }
    #[automatically_derived]
    impl ::routh::__private::Routhian for Gyrostat {
        #[inline]
        fn psi_dot(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t131: __F64 = __v3 * __t91;
            let __t132: __F64 = __v4 * __t95;
            let __t133: __F64 = __v5 * __t99;
            let __t134: __F64 = __t131 + __t132;
            let __t135: __F64 = __t133 + __t134;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t158: __F64 = __v6 - __t135;
            let __t160: __F64 = __t158 / __t155;
            __t160
        }
        #[inline]
        fn routhian(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v0 * __t36;
            let __t48: __F64 = __v1 * __t41;
            let __t49: __F64 = __v2 * __t46;
            let __t50: __F64 = __t47 + __t48;
            let __t51: __F64 = __t49 + __t50;
            let __t52: __F64 = 0.5f64 * __t51;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t71: __F64 = __v0 * __t68;
            let __t72: __F64 = __v1 * __t69;
            let __t73: __F64 = __v2 * __t70;
            let __t74: __F64 = __t71 + __t72;
            let __t75: __F64 = __t73 + __t74;
            let __t76: __F64 = __v28 * __v29;
            let __t77: __F64 = __v3 * __v25;
            let __t78: __F64 = __v4 * __v26;
            let __t79: __F64 = __v5 * __v27;
            let __t80: __F64 = __t77 + __t78;
            let __t81: __F64 = __t79 + __t80;
            let __t82: __F64 = __t76 * __t81;
            let __t84: __F64 = __t75 - __t82;
            let __t85: __F64 = __t52 + __t84;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t131: __F64 = __v3 * __t91;
            let __t132: __F64 = __v4 * __t95;
            let __t133: __F64 = __v5 * __t99;
            let __t134: __F64 = __t131 + __t132;
            let __t135: __F64 = __t133 + __t134;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t158: __F64 = __v6 - __t135;
            let __t160: __F64 = __t158 / __t155;
            let __t162: __F64 = __t158 * __t160;
            let __t165: __F64 = (-0.5f64) * __t162;
            let __t166: __F64 = __t85 + __t165;
            __t166
        }
        #[inline]
        fn dr_domega(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Vector3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t131: __F64 = __v3 * __t91;
            let __t132: __F64 = __v4 * __t95;
            let __t133: __F64 = __v5 * __t99;
            let __t134: __F64 = __t131 + __t132;
            let __t135: __F64 = __t133 + __t134;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t158: __F64 = __v6 - __t135;
            let __t160: __F64 = __t158 / __t155;
            let __t343: __F64 = __t140 * __t160;
            let __t344: __F64 = __t91 + __t343;
            let __t345: __F64 = __t145 * __t160;
            let __t346: __F64 = __t95 + __t345;
            let __t347: __F64 = __t150 * __t160;
            let __t348: __F64 = __t99 + __t347;
            __Vector3::new(__t344, __t346, __t348)
        }
        #[inline]
        fn dr_dgamma(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Vector3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t76: __F64 = __v28 * __v29;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t100: __F64 = __v25 * __t76;
            let __t102: __F64 = __v1 * __v19;
            let __t103: __F64 = __v0 * __v16;
            let __t104: __F64 = __t102 + __t103;
            let __t105: __F64 = __v2 * __v22;
            let __t106: __F64 = __t104 + __t105;
            let __t107: __F64 = __t106 - __t100;
            let __t108: __F64 = __v26 * __t76;
            let __t110: __F64 = __v1 * __v20;
            let __t111: __F64 = __v0 * __v17;
            let __t112: __F64 = __t110 + __t111;
            let __t113: __F64 = __v2 * __v23;
            let __t114: __F64 = __t112 + __t113;
            let __t115: __F64 = __t114 - __t108;
            let __t116: __F64 = __v27 * __t76;
            let __t118: __F64 = __v1 * __v21;
            let __t119: __F64 = __v0 * __v18;
            let __t120: __F64 = __t118 + __t119;
            let __t121: __F64 = __v2 * __v24;
            let __t122: __F64 = __t120 + __t121;
            let __t123: __F64 = __t122 - __t116;
            let __t131: __F64 = __v3 * __t91;
            let __t132: __F64 = __v4 * __t95;
            let __t133: __F64 = __v5 * __t99;
            let __t134: __F64 = __t131 + __t132;
            let __t135: __F64 = __t133 + __t134;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t158: __F64 = __v6 - __t135;
            let __t160: __F64 = __t158 / __t155;
            let __t180: __F64 = __v4 * __v19;
            let __t181: __F64 = __t53 + __t91;
            let __t182: __F64 = __t180 + __t181;
            let __t183: __F64 = __v5 * __v22;
            let __t184: __F64 = __t182 + __t183;
            let __t193: __F64 = __t59 + __t95;
            let __t194: __F64 = __v3 * __v17;
            let __t195: __F64 = __t193 + __t194;
            let __t196: __F64 = __v5 * __v23;
            let __t197: __F64 = __t195 + __t196;
            let __t206: __F64 = __v4 * __v21;
            let __t207: __F64 = __v3 * __v18;
            let __t208: __F64 = __t206 + __t207;
            let __t209: __F64 = __t65 + __t99;
            let __t210: __F64 = __t208 + __t209;
            let __t337: __F64 = __t160 * __t160;
            let __t349: __F64 = __t160 * __t184;
            let __t350: __F64 = __t107 + __t349;
            let __t351: __F64 = __t140 * __t337;
            let __t353: __F64 = __t350 + __t351;
            let __t354: __F64 = __t160 * __t197;
            let __t355: __F64 = __t115 + __t354;
            let __t356: __F64 = __t145 * __t337;
            let __t358: __F64 = __t355 + __t356;
            let __t359: __F64 = __t160 * __t210;
            let __t360: __F64 = __t123 + __t359;
            let __t361: __F64 = __t150 * __t337;
            let __t363: __F64 = __t360 + __t361;
            __Vector3::new(__t353, __t358, __t363)
        }
        #[inline]
        fn dr_dp(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t131: __F64 = __v3 * __t91;
            let __t132: __F64 = __v4 * __t95;
            let __t133: __F64 = __v5 * __t99;
            let __t134: __F64 = __t131 + __t132;
            let __t135: __F64 = __t133 + __t134;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t158: __F64 = __v6 - __t135;
            let __t160: __F64 = __t158 / __t155;
            let __t455: __F64 = -__t160;
            __t455
        }
        #[inline]
        fn d2r_domega2(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t159: __F64 = 1.0f64 / __t155;
            let __t226: __F64 = __t140 * __t159;
            let __t227: __F64 = __t145 * __t159;
            let __t228: __F64 = __t150 * __t159;
            let __t232: __F64 = __t140 * __t226;
            let __t234: __F64 = __v7 - __t232;
            let __t235: __F64 = __t145 * __t226;
            let __t237: __F64 = __v8 - __t235;
            let __t238: __F64 = __t150 * __t226;
            let __t240: __F64 = __v9 - __t238;
            let __t256: __F64 = __t145 * __t227;
            let __t258: __F64 = __v10 - __t256;
            let __t259: __F64 = __t150 * __t227;
            let __t261: __F64 = __v11 - __t259;
            let __t276: __F64 = __t150 * __t228;
            let __t278: __F64 = __v12 - __t276;
            __Matrix3::new(
                __t234,
                __t237,
                __t240,
                __t237,
                __t258,
                __t261,
                __t240,
                __t261,
                __t278,
            )
        }
        #[inline]
        fn d2r_domega_dgamma(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t131: __F64 = __v3 * __t91;
            let __t132: __F64 = __v4 * __t95;
            let __t133: __F64 = __v5 * __t99;
            let __t134: __F64 = __t131 + __t132;
            let __t135: __F64 = __t133 + __t134;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t158: __F64 = __v6 - __t135;
            let __t159: __F64 = 1.0f64 / __t155;
            let __t160: __F64 = __t158 * __t159;
            let __t180: __F64 = __v4 * __v19;
            let __t181: __F64 = __t53 + __t91;
            let __t182: __F64 = __t180 + __t181;
            let __t183: __F64 = __v5 * __v22;
            let __t184: __F64 = __t182 + __t183;
            let __t193: __F64 = __t59 + __t95;
            let __t194: __F64 = __v3 * __v17;
            let __t195: __F64 = __t193 + __t194;
            let __t196: __F64 = __v5 * __v23;
            let __t197: __F64 = __t195 + __t196;
            let __t206: __F64 = __v4 * __v21;
            let __t207: __F64 = __v3 * __v18;
            let __t208: __F64 = __t206 + __t207;
            let __t209: __F64 = __t65 + __t99;
            let __t210: __F64 = __t208 + __t209;
            let __t226: __F64 = __t140 * __t159;
            let __t227: __F64 = __t145 * __t159;
            let __t228: __F64 = __t150 * __t159;
            let __t343: __F64 = __t140 * __t160;
            let __t345: __F64 = __t145 * __t160;
            let __t347: __F64 = __t150 * __t160;
            let __t365: __F64 = 2f64 * __t343;
            let __t366: __F64 = __t184 + __t365;
            let __t367: __F64 = 2f64 * __t345;
            let __t368: __F64 = __t197 + __t367;
            let __t369: __F64 = 2f64 * __t347;
            let __t370: __F64 = __t210 + __t369;
            let __t374: __F64 = __v7 * __t160;
            let __t375: __F64 = __v16 + __t374;
            let __t376: __F64 = __t226 * __t366;
            let __t378: __F64 = __t375 - __t376;
            let __t379: __F64 = __v8 * __t160;
            let __t380: __F64 = __v17 + __t379;
            let __t381: __F64 = __t226 * __t368;
            let __t383: __F64 = __t380 - __t381;
            let __t384: __F64 = __v9 * __t160;
            let __t385: __F64 = __v18 + __t384;
            let __t386: __F64 = __t226 * __t370;
            let __t388: __F64 = __t385 - __t386;
            let __t389: __F64 = __v19 + __t379;
            let __t390: __F64 = __t227 * __t366;
            let __t392: __F64 = __t389 - __t390;
            let __t393: __F64 = __v10 * __t160;
            let __t394: __F64 = __v20 + __t393;
            let __t395: __F64 = __t227 * __t368;
            let __t397: __F64 = __t394 - __t395;
            let __t398: __F64 = __v11 * __t160;
            let __t399: __F64 = __v21 + __t398;
            let __t400: __F64 = __t227 * __t370;
            let __t402: __F64 = __t399 - __t400;
            let __t403: __F64 = __v22 + __t384;
            let __t404: __F64 = __t228 * __t366;
            let __t406: __F64 = __t403 - __t404;
            let __t407: __F64 = __v23 + __t398;
            let __t408: __F64 = __t228 * __t368;
            let __t410: __F64 = __t407 - __t408;
            let __t411: __F64 = __v12 * __t160;
            let __t412: __F64 = __v24 + __t411;
            let __t413: __F64 = __t228 * __t370;
            let __t415: __F64 = __t412 - __t413;
            __Matrix3::new(
                __t378,
                __t383,
                __t388,
                __t392,
                __t397,
                __t402,
                __t406,
                __t410,
                __t415,
            )
        }
        #[inline]
        fn d2r_dgamma2(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t131: __F64 = __v3 * __t91;
            let __t132: __F64 = __v4 * __t95;
            let __t133: __F64 = __v5 * __t99;
            let __t134: __F64 = __t131 + __t132;
            let __t135: __F64 = __t133 + __t134;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t158: __F64 = __v6 - __t135;
            let __t159: __F64 = 1.0f64 / __t155;
            let __t160: __F64 = __t158 * __t159;
            let __t180: __F64 = __v4 * __v19;
            let __t181: __F64 = __t53 + __t91;
            let __t182: __F64 = __t180 + __t181;
            let __t183: __F64 = __v5 * __v22;
            let __t184: __F64 = __t182 + __t183;
            let __t193: __F64 = __t59 + __t95;
            let __t194: __F64 = __v3 * __v17;
            let __t195: __F64 = __t193 + __t194;
            let __t196: __F64 = __v5 * __v23;
            let __t197: __F64 = __t195 + __t196;
            let __t206: __F64 = __v4 * __v21;
            let __t207: __F64 = __v3 * __v18;
            let __t208: __F64 = __t206 + __t207;
            let __t209: __F64 = __t65 + __t99;
            let __t210: __F64 = __t208 + __t209;
            let __t301: __F64 = __v17 + __v19;
            let __t308: __F64 = __v18 + __v22;
            let __t323: __F64 = __v21 + __v23;
            let __t337: __F64 = __t160 * __t160;
            let __t343: __F64 = __t140 * __t160;
            let __t345: __F64 = __t145 * __t160;
            let __t347: __F64 = __t150 * __t160;
            let __t365: __F64 = 2f64 * __t343;
            let __t366: __F64 = __t184 + __t365;
            let __t367: __F64 = 2f64 * __t345;
            let __t368: __F64 = __t197 + __t367;
            let __t369: __F64 = 2f64 * __t347;
            let __t370: __F64 = __t210 + __t369;
            let __t371: __F64 = __t159 * __t366;
            let __t372: __F64 = __t159 * __t368;
            let __t373: __F64 = __t159 * __t370;
            let __t416: __F64 = __v7 * __t337;
            let __t417: __F64 = __v16 * __t160;
            let __t418: __F64 = 2f64 * __t417;
            let __t419: __F64 = __t416 + __t418;
            let __t420: __F64 = __t366 * __t371;
            let __t422: __F64 = __t419 - __t420;
            let __t423: __F64 = __v8 * __t337;
            let __t424: __F64 = __t160 * __t301;
            let __t425: __F64 = __t423 + __t424;
            let __t426: __F64 = __t368 * __t371;
            let __t428: __F64 = __t425 - __t426;
            let __t429: __F64 = __v9 * __t337;
            let __t430: __F64 = __t160 * __t308;
            let __t431: __F64 = __t429 + __t430;
            let __t432: __F64 = __t370 * __t371;
            let __t434: __F64 = __t431 - __t432;
            let __t435: __F64 = __v10 * __t337;
            let __t436: __F64 = __v20 * __t160;
            let __t437: __F64 = 2f64 * __t436;
            let __t438: __F64 = __t435 + __t437;
            let __t439: __F64 = __t368 * __t372;
            let __t441: __F64 = __t438 - __t439;
            let __t442: __F64 = __v11 * __t337;
            let __t443: __F64 = __t160 * __t323;
            let __t444: __F64 = __t442 + __t443;
            let __t445: __F64 = __t370 * __t372;
            let __t447: __F64 = __t444 - __t445;
            let __t448: __F64 = __v12 * __t337;
            let __t449: __F64 = __v24 * __t160;
            let __t450: __F64 = 2f64 * __t449;
            let __t451: __F64 = __t448 + __t450;
            let __t452: __F64 = __t370 * __t373;
            let __t454: __F64 = __t451 - __t452;
            __Matrix3::new(
                __t422,
                __t428,
                __t434,
                __t428,
                __t441,
                __t447,
                __t434,
                __t447,
                __t454,
            )
        }
        #[inline]
        fn amended_potential(&self, __gamma: &__Vector3, __p_psi: __F64) -> __F64 {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t76: __F64 = __v28 * __v29;
            let __t77: __F64 = __v3 * __v25;
            let __t78: __F64 = __v4 * __v26;
            let __t79: __F64 = __v5 * __v27;
            let __t80: __F64 = __t77 + __t78;
            let __t81: __F64 = __t79 + __t80;
            let __t82: __F64 = __t76 * __t81;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t456: __F64 = __v3 * __t68;
            let __t457: __F64 = __v4 * __t69;
            let __t458: __F64 = __v5 * __t70;
            let __t459: __F64 = __t456 + __t457;
            let __t460: __F64 = __t458 + __t459;
            let __t462: __F64 = __v6 - __t460;
            let __t463: __F64 = __t462 / __t155;
            let __t465: __F64 = __t462 * __t463;
            let __t467: __F64 = (-0.5f64) * __t465;
            let __t468: __F64 = __t467 - __t82;
            let __t661: __F64 = -__t468;
            __t661
        }
        #[inline]
        fn bundle(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __RouthBundle {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t32: __F64 = __v0 * __v7;
            let __t33: __F64 = __v1 * __v8;
            let __t34: __F64 = __v2 * __v9;
            let __t35: __F64 = __t32 + __t33;
            let __t36: __F64 = __t34 + __t35;
            let __t37: __F64 = __v0 * __v8;
            let __t38: __F64 = __v1 * __v10;
            let __t39: __F64 = __v2 * __v11;
            let __t40: __F64 = __t37 + __t38;
            let __t41: __F64 = __t39 + __t40;
            let __t42: __F64 = __v0 * __v9;
            let __t43: __F64 = __v1 * __v11;
            let __t44: __F64 = __v2 * __v12;
            let __t45: __F64 = __t42 + __t43;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v0 * __t36;
            let __t48: __F64 = __v1 * __t41;
            let __t49: __F64 = __v2 * __t46;
            let __t50: __F64 = __t47 + __t48;
            let __t51: __F64 = __t49 + __t50;
            let __t52: __F64 = 0.5f64 * __t51;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t71: __F64 = __v0 * __t68;
            let __t72: __F64 = __v1 * __t69;
            let __t73: __F64 = __v2 * __t70;
            let __t74: __F64 = __t71 + __t72;
            let __t75: __F64 = __t73 + __t74;
            let __t76: __F64 = __v28 * __v29;
            let __t77: __F64 = __v3 * __v25;
            let __t78: __F64 = __v4 * __v26;
            let __t79: __F64 = __v5 * __v27;
            let __t80: __F64 = __t77 + __t78;
            let __t81: __F64 = __t79 + __t80;
            let __t82: __F64 = __t76 * __t81;
            let __t84: __F64 = __t75 - __t82;
            let __t85: __F64 = __t52 + __t84;
            let __t91: __F64 = __t36 + __t68;
            let __t95: __F64 = __t41 + __t69;
            let __t99: __F64 = __t46 + __t70;
            let __t100: __F64 = __v25 * __t76;
            let __t102: __F64 = __v1 * __v19;
            let __t103: __F64 = __v0 * __v16;
            let __t104: __F64 = __t102 + __t103;
            let __t105: __F64 = __v2 * __v22;
            let __t106: __F64 = __t104 + __t105;
            let __t107: __F64 = __t106 - __t100;
            let __t108: __F64 = __v26 * __t76;
            let __t110: __F64 = __v1 * __v20;
            let __t111: __F64 = __v0 * __v17;
            let __t112: __F64 = __t110 + __t111;
            let __t113: __F64 = __v2 * __v23;
            let __t114: __F64 = __t112 + __t113;
            let __t115: __F64 = __t114 - __t108;
            let __t116: __F64 = __v27 * __t76;
            let __t118: __F64 = __v1 * __v21;
            let __t119: __F64 = __v0 * __v18;
            let __t120: __F64 = __t118 + __t119;
            let __t121: __F64 = __v2 * __v24;
            let __t122: __F64 = __t120 + __t121;
            let __t123: __F64 = __t122 - __t116;
            let __t131: __F64 = __v3 * __t91;
            let __t132: __F64 = __v4 * __t95;
            let __t133: __F64 = __v5 * __t99;
            let __t134: __F64 = __t131 + __t132;
            let __t135: __F64 = __t133 + __t134;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t158: __F64 = __v6 - __t135;
            let __t159: __F64 = 1.0f64 / __t155;
            let __t160: __F64 = __t158 * __t159;
            let __t162: __F64 = __t158 * __t160;
            let __t165: __F64 = (-0.5f64) * __t162;
            let __t166: __F64 = __t85 + __t165;
            let __t180: __F64 = __v4 * __v19;
            let __t181: __F64 = __t53 + __t91;
            let __t182: __F64 = __t180 + __t181;
            let __t183: __F64 = __v5 * __v22;
            let __t184: __F64 = __t182 + __t183;
            let __t193: __F64 = __t59 + __t95;
            let __t194: __F64 = __v3 * __v17;
            let __t195: __F64 = __t193 + __t194;
            let __t196: __F64 = __v5 * __v23;
            let __t197: __F64 = __t195 + __t196;
            let __t206: __F64 = __v4 * __v21;
            let __t207: __F64 = __v3 * __v18;
            let __t208: __F64 = __t206 + __t207;
            let __t209: __F64 = __t65 + __t99;
            let __t210: __F64 = __t208 + __t209;
            let __t226: __F64 = __t140 * __t159;
            let __t227: __F64 = __t145 * __t159;
            let __t228: __F64 = __t150 * __t159;
            let __t232: __F64 = __t140 * __t226;
            let __t234: __F64 = __v7 - __t232;
            let __t235: __F64 = __t145 * __t226;
            let __t237: __F64 = __v8 - __t235;
            let __t238: __F64 = __t150 * __t226;
            let __t240: __F64 = __v9 - __t238;
            let __t256: __F64 = __t145 * __t227;
            let __t258: __F64 = __v10 - __t256;
            let __t259: __F64 = __t150 * __t227;
            let __t261: __F64 = __v11 - __t259;
            let __t276: __F64 = __t150 * __t228;
            let __t278: __F64 = __v12 - __t276;
            let __t301: __F64 = __v17 + __v19;
            let __t308: __F64 = __v18 + __v22;
            let __t323: __F64 = __v21 + __v23;
            let __t337: __F64 = __t160 * __t160;
            let __t343: __F64 = __t140 * __t160;
            let __t344: __F64 = __t91 + __t343;
            let __t345: __F64 = __t145 * __t160;
            let __t346: __F64 = __t95 + __t345;
            let __t347: __F64 = __t150 * __t160;
            let __t348: __F64 = __t99 + __t347;
            let __t349: __F64 = __t160 * __t184;
            let __t350: __F64 = __t107 + __t349;
            let __t351: __F64 = __t140 * __t337;
            let __t353: __F64 = __t350 + __t351;
            let __t354: __F64 = __t160 * __t197;
            let __t355: __F64 = __t115 + __t354;
            let __t356: __F64 = __t145 * __t337;
            let __t358: __F64 = __t355 + __t356;
            let __t359: __F64 = __t160 * __t210;
            let __t360: __F64 = __t123 + __t359;
            let __t361: __F64 = __t150 * __t337;
            let __t363: __F64 = __t360 + __t361;
            let __t365: __F64 = 2f64 * __t343;
            let __t366: __F64 = __t184 + __t365;
            let __t367: __F64 = 2f64 * __t345;
            let __t368: __F64 = __t197 + __t367;
            let __t369: __F64 = 2f64 * __t347;
            let __t370: __F64 = __t210 + __t369;
            let __t371: __F64 = __t159 * __t366;
            let __t372: __F64 = __t159 * __t368;
            let __t373: __F64 = __t159 * __t370;
            let __t374: __F64 = __v7 * __t160;
            let __t375: __F64 = __v16 + __t374;
            let __t376: __F64 = __t226 * __t366;
            let __t378: __F64 = __t375 - __t376;
            let __t379: __F64 = __v8 * __t160;
            let __t380: __F64 = __v17 + __t379;
            let __t381: __F64 = __t226 * __t368;
            let __t383: __F64 = __t380 - __t381;
            let __t384: __F64 = __v9 * __t160;
            let __t385: __F64 = __v18 + __t384;
            let __t386: __F64 = __t226 * __t370;
            let __t388: __F64 = __t385 - __t386;
            let __t389: __F64 = __v19 + __t379;
            let __t390: __F64 = __t227 * __t366;
            let __t392: __F64 = __t389 - __t390;
            let __t393: __F64 = __v10 * __t160;
            let __t394: __F64 = __v20 + __t393;
            let __t395: __F64 = __t227 * __t368;
            let __t397: __F64 = __t394 - __t395;
            let __t398: __F64 = __v11 * __t160;
            let __t399: __F64 = __v21 + __t398;
            let __t400: __F64 = __t227 * __t370;
            let __t402: __F64 = __t399 - __t400;
            let __t403: __F64 = __v22 + __t384;
            let __t404: __F64 = __t228 * __t366;
            let __t406: __F64 = __t403 - __t404;
            let __t407: __F64 = __v23 + __t398;
            let __t408: __F64 = __t228 * __t368;
            let __t410: __F64 = __t407 - __t408;
            let __t411: __F64 = __v12 * __t160;
            let __t412: __F64 = __v24 + __t411;
            let __t413: __F64 = __t228 * __t370;
            let __t415: __F64 = __t412 - __t413;
            let __t416: __F64 = __v7 * __t337;
            let __t417: __F64 = __v16 * __t160;
            let __t418: __F64 = 2f64 * __t417;
            let __t419: __F64 = __t416 + __t418;
            let __t420: __F64 = __t366 * __t371;
            let __t422: __F64 = __t419 - __t420;
            let __t423: __F64 = __v8 * __t337;
            let __t424: __F64 = __t160 * __t301;
            let __t425: __F64 = __t423 + __t424;
            let __t426: __F64 = __t368 * __t371;
            let __t428: __F64 = __t425 - __t426;
            let __t429: __F64 = __v9 * __t337;
            let __t430: __F64 = __t160 * __t308;
            let __t431: __F64 = __t429 + __t430;
            let __t432: __F64 = __t370 * __t371;
            let __t434: __F64 = __t431 - __t432;
            let __t435: __F64 = __v10 * __t337;
            let __t436: __F64 = __v20 * __t160;
            let __t437: __F64 = 2f64 * __t436;
            let __t438: __F64 = __t435 + __t437;
            let __t439: __F64 = __t368 * __t372;
            let __t441: __F64 = __t438 - __t439;
            let __t442: __F64 = __v11 * __t337;
            let __t443: __F64 = __t160 * __t323;
            let __t444: __F64 = __t442 + __t443;
            let __t445: __F64 = __t370 * __t372;
            let __t447: __F64 = __t444 - __t445;
            let __t448: __F64 = __v12 * __t337;
            let __t449: __F64 = __v24 * __t160;
            let __t450: __F64 = 2f64 * __t449;
            let __t451: __F64 = __t448 + __t450;
            let __t452: __F64 = __t370 * __t373;
            let __t454: __F64 = __t451 - __t452;
            let __t455: __F64 = -__t160;
            __RouthBundle {
                routhian: __t166,
                psi_dot: __t160,
                dr_domega: __Vector3::new(__t344, __t346, __t348),
                dr_dgamma: __Vector3::new(__t353, __t358, __t363),
                dr_dp: __t455,
                d2r_domega2: __Matrix3::new(
                    __t234,
                    __t237,
                    __t240,
                    __t237,
                    __t258,
                    __t261,
                    __t240,
                    __t261,
                    __t278,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t378,
                    __t383,
                    __t388,
                    __t392,
                    __t397,
                    __t402,
                    __t406,
                    __t410,
                    __t415,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t422,
                    __t428,
                    __t434,
                    __t428,
                    __t441,
                    __t447,
                    __t434,
                    __t447,
                    __t454,
                ),
            }
        }
        #[inline]
        fn gyroscopic_system(
            &self,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __GyroscopicSystem {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t53: __F64 = __v3 * __v16;
            let __t54: __F64 = __v4 * __v17;
            let __t55: __F64 = __v5 * __v18;
            let __t56: __F64 = __t53 + __t54;
            let __t57: __F64 = __t55 + __t56;
            let __t58: __F64 = __v3 * __v19;
            let __t59: __F64 = __v4 * __v20;
            let __t60: __F64 = __v5 * __v21;
            let __t61: __F64 = __t58 + __t59;
            let __t62: __F64 = __t60 + __t61;
            let __t63: __F64 = __v3 * __v22;
            let __t64: __F64 = __v4 * __v23;
            let __t65: __F64 = __v5 * __v24;
            let __t66: __F64 = __t63 + __t64;
            let __t67: __F64 = __t65 + __t66;
            let __t68: __F64 = __v13 + __t57;
            let __t69: __F64 = __v14 + __t62;
            let __t70: __F64 = __v15 + __t67;
            let __t76: __F64 = __v28 * __v29;
            let __t100: __F64 = __v25 * __t76;
            let __t108: __F64 = __v26 * __t76;
            let __t116: __F64 = __v27 * __t76;
            let __t136: __F64 = __v3 * __v7;
            let __t137: __F64 = __v4 * __v8;
            let __t138: __F64 = __v5 * __v9;
            let __t139: __F64 = __t136 + __t137;
            let __t140: __F64 = __t138 + __t139;
            let __t141: __F64 = __v3 * __v8;
            let __t142: __F64 = __v4 * __v10;
            let __t143: __F64 = __v5 * __v11;
            let __t144: __F64 = __t141 + __t142;
            let __t145: __F64 = __t143 + __t144;
            let __t146: __F64 = __v3 * __v9;
            let __t147: __F64 = __v4 * __v11;
            let __t148: __F64 = __v5 * __v12;
            let __t149: __F64 = __t146 + __t147;
            let __t150: __F64 = __t148 + __t149;
            let __t151: __F64 = __v3 * __t140;
            let __t152: __F64 = __v4 * __t145;
            let __t153: __F64 = __v5 * __t150;
            let __t154: __F64 = __t151 + __t152;
            let __t155: __F64 = __t153 + __t154;
            let __t159: __F64 = 1.0f64 / __t155;
            let __t180: __F64 = __v4 * __v19;
            let __t183: __F64 = __v5 * __v22;
            let __t194: __F64 = __v3 * __v17;
            let __t196: __F64 = __v5 * __v23;
            let __t206: __F64 = __v4 * __v21;
            let __t207: __F64 = __v3 * __v18;
            let __t208: __F64 = __t206 + __t207;
            let __t226: __F64 = __t140 * __t159;
            let __t227: __F64 = __t145 * __t159;
            let __t228: __F64 = __t150 * __t159;
            let __t232: __F64 = __t140 * __t226;
            let __t234: __F64 = __v7 - __t232;
            let __t235: __F64 = __t145 * __t226;
            let __t237: __F64 = __v8 - __t235;
            let __t238: __F64 = __t150 * __t226;
            let __t240: __F64 = __v9 - __t238;
            let __t256: __F64 = __t145 * __t227;
            let __t258: __F64 = __v10 - __t256;
            let __t259: __F64 = __t150 * __t227;
            let __t261: __F64 = __v11 - __t259;
            let __t276: __F64 = __t150 * __t228;
            let __t278: __F64 = __v12 - __t276;
            let __t301: __F64 = __v17 + __v19;
            let __t308: __F64 = __v18 + __v22;
            let __t323: __F64 = __v21 + __v23;
            let __t456: __F64 = __v3 * __t68;
            let __t457: __F64 = __v4 * __t69;
            let __t458: __F64 = __v5 * __t70;
            let __t459: __F64 = __t456 + __t457;
            let __t460: __F64 = __t458 + __t459;
            let __t462: __F64 = __v6 - __t460;
            let __t463: __F64 = __t159 * __t462;
            let __t475: __F64 = __t53 + __t68;
            let __t476: __F64 = __t180 + __t475;
            let __t477: __F64 = __t183 + __t476;
            let __t481: __F64 = __t59 + __t69;
            let __t482: __F64 = __t194 + __t481;
            let __t483: __F64 = __t196 + __t482;
            let __t487: __F64 = __t65 + __t70;
            let __t488: __F64 = __t208 + __t487;
            let __t543: __F64 = __t463 * __t463;
            let __t549: __F64 = __t140 * __t463;
            let __t550: __F64 = __t68 + __t549;
            let __t551: __F64 = __t145 * __t463;
            let __t552: __F64 = __t69 + __t551;
            let __t553: __F64 = __t150 * __t463;
            let __t554: __F64 = __t70 + __t553;
            let __t555: __F64 = __t463 * __t477;
            let __t556: __F64 = __t555 - __t100;
            let __t557: __F64 = __t140 * __t543;
            let __t559: __F64 = __t556 + __t557;
            let __t560: __F64 = __t463 * __t483;
            let __t561: __F64 = __t560 - __t108;
            let __t562: __F64 = __t145 * __t543;
            let __t564: __F64 = __t561 + __t562;
            let __t565: __F64 = __t463 * __t488;
            let __t566: __F64 = __t565 - __t116;
            let __t567: __F64 = __t150 * __t543;
            let __t569: __F64 = __t566 + __t567;
            let __t571: __F64 = 2f64 * __t549;
            let __t572: __F64 = __t477 + __t571;
            let __t573: __F64 = 2f64 * __t551;
            let __t574: __F64 = __t483 + __t573;
            let __t575: __F64 = 2f64 * __t553;
            let __t576: __F64 = __t488 + __t575;
            let __t577: __F64 = __t159 * __t572;
            let __t578: __F64 = __t159 * __t574;
            let __t579: __F64 = __t159 * __t576;
            let __t580: __F64 = __v7 * __t463;
            let __t581: __F64 = __v16 + __t580;
            let __t582: __F64 = __t226 * __t572;
            let __t584: __F64 = __t581 - __t582;
            let __t585: __F64 = __v8 * __t463;
            let __t586: __F64 = __v17 + __t585;
            let __t587: __F64 = __t226 * __t574;
            let __t589: __F64 = __t586 - __t587;
            let __t590: __F64 = __v9 * __t463;
            let __t591: __F64 = __v18 + __t590;
            let __t592: __F64 = __t226 * __t576;
            let __t594: __F64 = __t591 - __t592;
            let __t595: __F64 = __v19 + __t585;
            let __t596: __F64 = __t227 * __t572;
            let __t598: __F64 = __t595 - __t596;
            let __t599: __F64 = __v10 * __t463;
            let __t600: __F64 = __v20 + __t599;
            let __t601: __F64 = __t227 * __t574;
            let __t603: __F64 = __t600 - __t601;
            let __t604: __F64 = __v11 * __t463;
            let __t605: __F64 = __v21 + __t604;
            let __t606: __F64 = __t227 * __t576;
            let __t608: __F64 = __t605 - __t606;
            let __t609: __F64 = __v22 + __t590;
            let __t610: __F64 = __t228 * __t572;
            let __t612: __F64 = __t609 - __t610;
            let __t613: __F64 = __v23 + __t604;
            let __t614: __F64 = __t228 * __t574;
            let __t616: __F64 = __t613 - __t614;
            let __t617: __F64 = __v12 * __t463;
            let __t618: __F64 = __v24 + __t617;
            let __t619: __F64 = __t228 * __t576;
            let __t621: __F64 = __t618 - __t619;
            let __t622: __F64 = __v7 * __t543;
            let __t623: __F64 = __v16 * __t463;
            let __t624: __F64 = 2f64 * __t623;
            let __t625: __F64 = __t622 + __t624;
            let __t626: __F64 = __t572 * __t577;
            let __t628: __F64 = __t625 - __t626;
            let __t629: __F64 = __v8 * __t543;
            let __t630: __F64 = __t301 * __t463;
            let __t631: __F64 = __t629 + __t630;
            let __t632: __F64 = __t574 * __t577;
            let __t634: __F64 = __t631 - __t632;
            let __t635: __F64 = __v9 * __t543;
            let __t636: __F64 = __t308 * __t463;
            let __t637: __F64 = __t635 + __t636;
            let __t638: __F64 = __t576 * __t577;
            let __t640: __F64 = __t637 - __t638;
            let __t641: __F64 = __v10 * __t543;
            let __t642: __F64 = __v20 * __t463;
            let __t643: __F64 = 2f64 * __t642;
            let __t644: __F64 = __t641 + __t643;
            let __t645: __F64 = __t574 * __t578;
            let __t647: __F64 = __t644 - __t645;
            let __t648: __F64 = __v11 * __t543;
            let __t649: __F64 = __t323 * __t463;
            let __t650: __F64 = __t648 + __t649;
            let __t651: __F64 = __t576 * __t578;
            let __t653: __F64 = __t650 - __t651;
            let __t654: __F64 = __v12 * __t543;
            let __t655: __F64 = __v24 * __t463;
            let __t656: __F64 = 2f64 * __t655;
            let __t657: __F64 = __t654 + __t656;
            let __t658: __F64 = __t576 * __t579;
            let __t660: __F64 = __t657 - __t658;
            let __t672: __F64 = __v5 * __t584;
            let __t674: __F64 = __v3 * __t594;
            let __t675: __F64 = __t674 - __t672;
            let __t676: __F64 = __v4 * __t584;
            let __t677: __F64 = __v3 * __t589;
            let __t679: __F64 = __t676 - __t677;
            let __t680: __F64 = __v5 * __t603;
            let __t681: __F64 = __v4 * __t608;
            let __t683: __F64 = __t680 - __t681;
            let __t688: __F64 = __v4 * __t598;
            let __t689: __F64 = __v3 * __t603;
            let __t691: __F64 = __t688 - __t689;
            let __t692: __F64 = __v5 * __t616;
            let __t693: __F64 = __v4 * __t621;
            let __t695: __F64 = __t692 - __t693;
            let __t696: __F64 = __v5 * __t612;
            let __t698: __F64 = __v3 * __t621;
            let __t699: __F64 = __t698 - __t696;
            let __t707: __F64 = __t681 - __t680;
            let __t709: __F64 = __t693 - __t692;
            let __t711: __F64 = __t672 - __t674;
            let __t715: __F64 = __t696 - __t698;
            let __t717: __F64 = __t677 - __t676;
            let __t719: __F64 = __t689 - __t688;
            let __t722: __F64 = __t675 + __t707;
            let __t723: __F64 = __t554 + __t722;
            let __t724: __F64 = 0.5f64 * __t723;
            let __t725: __F64 = __t679 + __t709;
            let __t726: __F64 = __t725 - __t552;
            let __t727: __F64 = 0.5f64 * __t726;
            let __t728: __F64 = __t683 + __t711;
            let __t729: __F64 = __t728 - __t554;
            let __t730: __F64 = 0.5f64 * __t729;
            let __t731: __F64 = __t691 + __t715;
            let __t732: __F64 = __t550 + __t731;
            let __t733: __F64 = 0.5f64 * __t732;
            let __t734: __F64 = __t695 + __t717;
            let __t735: __F64 = __t552 + __t734;
            let __t736: __F64 = 0.5f64 * __t735;
            let __t737: __F64 = __t699 + __t719;
            let __t738: __F64 = __t737 - __t550;
            let __t739: __F64 = 0.5f64 * __t738;
            let __t740: __F64 = __v3 * __t559;
            let __t741: __F64 = __v4 * __t564;
            let __t742: __F64 = __v5 * __t569;
            let __t743: __F64 = __t740 + __t741;
            let __t744: __F64 = __t742 + __t743;
            let __t746: __F64 = __t744 - __t628;
            let __t750: __F64 = __t744 - __t647;
            let __t753: __F64 = __t744 - __t660;
            let __t754: __F64 = __v5 * __t634;
            let __t756: __F64 = __v4 * __t640;
            let __t758: __F64 = __t756 - __t754;
            let __t759: __F64 = __v5 * __t750;
            let __t760: __F64 = __v4 * __t653;
            let __t762: __F64 = __t759 + __t760;
            let __t763: __F64 = __v5 * __t653;
            let __t765: __F64 = __v4 * __t753;
            let __t767: __F64 = __t763 + __t765;
            let __t769: __F64 = __v5 * __t746;
            let __t771: __F64 = __v3 * __t640;
            let __t773: __F64 = __t769 + __t771;
            let __t775: __F64 = __v3 * __t653;
            let __t777: __F64 = __t754 - __t775;
            let __t778: __F64 = __v5 * __t640;
            let __t780: __F64 = __v3 * __t753;
            let __t781: __F64 = __t778 + __t780;
            let __t782: __F64 = __v4 * __t746;
            let __t783: __F64 = __v3 * __t634;
            let __t785: __F64 = __t782 + __t783;
            let __t786: __F64 = __v4 * __t634;
            let __t788: __F64 = __v3 * __t750;
            let __t790: __F64 = __t786 + __t788;
            let __t792: __F64 = __t775 - __t756;
            let __t793: __F64 = __v5 * __t762;
            let __t794: __F64 = __v4 * __t767;
            let __t796: __F64 = __t793 + __t794;
            let __t797: __F64 = __v5 * __t758;
            let __t799: __F64 = __v3 * __t767;
            let __t801: __F64 = __t797 + __t799;
            let __t802: __F64 = -__t801;
            let __t803: __F64 = __v4 * __t758;
            let __t804: __F64 = __v3 * __t762;
            let __t806: __F64 = __t803 - __t804;
            let __t807: __F64 = __v5 * __t777;
            let __t808: __F64 = __v4 * __t781;
            let __t810: __F64 = __t807 - __t808;
            let __t811: __F64 = __v5 * __t773;
            let __t813: __F64 = __v3 * __t781;
            let __t814: __F64 = __t811 + __t813;
            let __t815: __F64 = __v4 * __t773;
            let __t817: __F64 = __v3 * __t777;
            let __t819: __F64 = __t815 + __t817;
            let __t820: __F64 = -__t819;
            let __t821: __F64 = __v5 * __t790;
            let __t823: __F64 = __v4 * __t792;
            let __t825: __F64 = __t821 + __t823;
            let __t826: __F64 = -__t825;
            let __t827: __F64 = __v5 * __t785;
            let __t829: __F64 = __v3 * __t792;
            let __t830: __F64 = __t829 - __t827;
            let __t831: __F64 = __v4 * __t785;
            let __t832: __F64 = __v3 * __t790;
            let __t834: __F64 = __t831 + __t832;
            __GyroscopicSystem {
                a: __Matrix3::new(
                    __t234,
                    __t237,
                    __t240,
                    __t237,
                    __t258,
                    __t261,
                    __t240,
                    __t261,
                    __t278,
                ),
                g: __Matrix3::new(
                    0f64,
                    __t724,
                    __t727,
                    __t730,
                    0f64,
                    __t733,
                    __t736,
                    __t739,
                    0f64,
                ),
                c: __Matrix3::new(
                    __t796,
                    __t802,
                    __t806,
                    __t810,
                    __t814,
                    __t820,
                    __t826,
                    __t830,
                    __t834,
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
